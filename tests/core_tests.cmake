# Core unit tests (GoogleTest, no MeshLab): one binary per core module.
gr_add_core_test(test_tri_mesh test_tri_mesh.cpp)
gr_add_core_test(test_fast_marching test_fast_marching.cpp)
gr_add_core_test(test_fast_marching_incremental test_fast_marching_incremental.cpp)
gr_add_core_test(test_fast_marching_shapes test_fast_marching_shapes.cpp)
gr_add_core_test(test_voronoi_boundary test_voronoi_boundary.cpp)
gr_add_core_test(test_geodesic_path test_geodesic_path.cpp)
