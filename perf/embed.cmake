# Re-embedding a synthesized texture over an edited base against synthesizing it (target: under a
# tenth of the synthesis time).
add_executable(embed_bench ${CMAKE_CURRENT_LIST_DIR}/embed_bench.cpp)
target_link_libraries(embed_bench PRIVATE meshquilt_shell meshquilt_quilt meshquilt_swatch meshquilt_mesh meshquilt_engine)

# L2 stretch of the shell map against line-search sweeps.
add_executable(stretch_bench ${CMAKE_CURRENT_LIST_DIR}/stretch_bench.cpp)
target_link_libraries(stretch_bench PRIVATE meshquilt_shell meshquilt_mesh meshquilt_engine)
