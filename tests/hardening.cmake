# Hardened inputs and outputs: reader limits (allocation-bounded), atomic writes, the CLI's
# memory budget, absurd swatches, SIGKILL/SIGINT during synth.
meshquilt_test(reader_limits_test SOURCES reader_limits_test.cpp LIBS meshquilt_swatch meshquilt_mesh)
meshquilt_test(atomic_write_test SOURCES atomic_write_test.cpp LIBS meshquilt_mesh)
meshquilt_test(hardening_cli_test NEEDS_CLI SOURCES hardening_cli_test.cpp LABELS end_to_end)
