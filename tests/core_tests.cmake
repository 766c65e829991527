# Core unit tests (GoogleTest, no MeshLab): one binary per core module.
gr_add_core_test(test_tri_mesh test_tri_mesh.cpp)
gr_add_core_test(test_fast_marching test_fast_marching.cpp)
gr_add_core_test(test_fast_marching_incremental test_fast_marching_incremental.cpp)
