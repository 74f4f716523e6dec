# The fuzz targets' seed corpora and regression files (tests/fuzz/), replayed through the same
# bodies as the libFuzzer targets in the normal and the sanitizer build.
meshquilt_test(fuzz_corpus_test SOURCES fuzz_corpus_test.cpp LIBS meshquilt_shell meshquilt_swatch meshquilt_quilt meshquilt_mesh)
target_compile_definitions(fuzz_corpus_test PRIVATE MESHQUILT_FUZZ_DIR="${CMAKE_CURRENT_SOURCE_DIR}/fuzz")
