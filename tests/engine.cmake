# The compute engine and its kernels: back-end parity against brute-force references.
meshquilt_test(engine_test SOURCES engine_test.cpp LIBS meshquilt_kernels meshquilt_engine)
meshquilt_test(matching_cost_test SOURCES matching_cost_test.cpp LIBS meshquilt_kernels meshquilt_spatial meshquilt_mesh meshquilt_engine)
meshquilt_test(stretch_linesearch_test SOURCES stretch_linesearch_test.cpp LIBS meshquilt_kernels meshquilt_engine)
