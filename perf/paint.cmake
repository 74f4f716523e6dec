# Time per vertex of paint.
add_executable(paint_bench ${CMAKE_CURRENT_LIST_DIR}/paint_bench.cpp)
target_link_libraries(paint_bench PRIVATE meshquilt_paint meshquilt_surface meshquilt_mesh)
