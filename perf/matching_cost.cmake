# Micro-benchmark of the matching_cost kernel on both back ends (pairs per second).
add_executable(matching_cost_bench ${CMAKE_CURRENT_LIST_DIR}/matching_cost_bench.cpp)
target_link_libraries(matching_cost_bench PRIVATE meshquilt_kernels meshquilt_spatial meshquilt_mesh meshquilt_engine benchmark::benchmark)
