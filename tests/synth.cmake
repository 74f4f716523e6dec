meshquilt_test(synth_bad_input_test NEEDS_CLI SOURCES synth_bad_input_test.cpp)
# slow: every test here quilts a whole plane; under ASan+UBSan (scripts/sanitize.sh leaves the
# label out) even the 1x1 one takes about 3 minutes and the 4x4 ones over 15.
meshquilt_test(planar_quilting_test NEEDS_CLI SOURCES planar_quilting_test.cpp
  LIBS meshquilt_quilt meshquilt_inspect meshquilt_swatch meshquilt_spatial meshquilt_mesh meshquilt_engine
  LABELS slow)
meshquilt_test(geometry_matching_test SOURCES geometry_matching_test.cpp
  LIBS meshquilt_quilt meshquilt_swatch meshquilt_spatial meshquilt_mesh meshquilt_kernels meshquilt_engine)
meshquilt_test(planar_golden_test NEEDS_CLI SOURCES planar_golden_test.cpp LABELS end_to_end)
meshquilt_test(curved_golden_test NEEDS_CLI SOURCES curved_golden_test.cpp LABELS end_to_end)
