# Integration tests through the real MeshLab 2020.09 (Debian's binaries) with our plugin staged.
find_package(Qt5 REQUIRED COMPONENTS Core Gui Widgets OpenGL Xml)
set(GR_STAGE_DIR ${CMAKE_BINARY_DIR}/stage)

# Fixture: a staged prefix whose plugins folder holds the freshly built plugin.
add_test(NAME stage_meshlab
         COMMAND bash ${PROJECT_SOURCE_DIR}/scripts/stage_meshlab.sh
                 $<TARGET_FILE:filter_geodesic_remesh> ${GR_STAGE_DIR})
set_tests_properties(stage_meshlab PROPERTIES FIXTURES_SETUP meshlab_stage LABELS integration)

add_executable(test_meshlabserver test_meshlabserver.cpp test_support.cpp)
target_link_libraries(test_meshlabserver PRIVATE gr_core GTest::gtest GTest::gtest_main)
target_compile_definitions(test_meshlabserver PRIVATE ${GR_TEST_DEFINES} GR_STAGE_DIR="${GR_STAGE_DIR}")
target_compile_options(test_meshlabserver PRIVATE ${GR_WARNINGS})
# Each xvfb-run needs its own X display: run these one at a time.
gtest_discover_tests(test_meshlabserver DISCOVERY_TIMEOUT 60
                     PROPERTIES FIXTURES_REQUIRED meshlab_stage RUN_SERIAL TRUE LABELS integration)

# The real GUI under Xvfb loads the staged plugin; the screenshot is kept as an artefact.
add_test(NAME gui_smoke
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/gui_smoke.sh ${GR_STAGE_DIR} ${GR_MESH_DIR}/fandisk.off
                 ${CMAKE_CURRENT_BINARY_DIR}/output/gui_smoke.png)
set_tests_properties(gui_smoke PROPERTIES FIXTURES_REQUIRED meshlab_stage RUN_SERIAL TRUE TIMEOUT 120
                     LABELS integration)

# The plugin class in-process on a MeshDocument of libmeshlab-common (no meshlabserver): checks
# that a failed filter leaves the mesh exactly as it was.
add_executable(test_filter_inprocess test_filter_inprocess.cpp test_support.cpp $<TARGET_OBJECTS:gr_filters>)
target_link_libraries(test_filter_inprocess PRIVATE gr_adapters ${MESHLAB_COMMON_LIB}
                      Qt5::Core Qt5::Gui Qt5::Widgets Qt5::OpenGL Qt5::Xml GTest::gtest GTest::gtest_main)
target_include_directories(test_filter_inprocess PRIVATE ${CMAKE_BINARY_DIR}/filter_geodesic_remesh/gr_filters_autogen/include)
target_compile_definitions(test_filter_inprocess PRIVATE ${GR_TEST_DEFINES})
gtest_discover_tests(test_filter_inprocess DISCOVERY_TIMEOUT 60 PROPERTIES LABELS filters)
