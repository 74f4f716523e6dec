# The shell embedding (host/shell): atlas, shell, shell map, stretch and its minimization, the
# concave corner of Figure 8, texture files and re-embedding.
meshquilt_test(shell_test SOURCES shell_test.cpp LIBS meshquilt_shell meshquilt_quilt meshquilt_spatial meshquilt_mesh meshquilt_engine)
meshquilt_test(embed_cli_test NEEDS_CLI SOURCES embed_cli_test.cpp LIBS meshquilt_spatial meshquilt_mesh LABELS end_to_end)
