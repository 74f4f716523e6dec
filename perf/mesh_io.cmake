# Writing and reading a 1,000,000-face mesh in every format.
add_executable(mesh_io_bench ${CMAKE_CURRENT_LIST_DIR}/mesh_io_bench.cpp)
target_link_libraries(mesh_io_bench PRIVATE meshquilt_mesh)
