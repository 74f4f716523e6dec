# The full inspect report on a 1,000,000-face mesh of 2,000 rings (target: < 20 s on 2 cores).
add_executable(inspect_bench ${CMAKE_CURRENT_LIST_DIR}/inspect_bench.cpp)
target_link_libraries(inspect_bench PRIVATE meshquilt_inspect meshquilt_spatial meshquilt_mesh)
