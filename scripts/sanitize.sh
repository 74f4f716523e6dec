#!/usr/bin/env bash
# The sanitizer stage of the tests: builds meshquilt with AddressSanitizer and
# UndefinedBehaviorSanitizer (GCC, the project's compiler) into build-asan/ and builds and runs
# every test except the labels end_to_end and slow (whole quilts, 3 to over 15 minutes each under the
# sanitizers). That keeps every unit test, the Vulkan tests on lavapipe (CI=true: a missing device
# fails) and the replay of the fuzz corpora (fuzz_corpus_test). Any memory error, leak or undefined
# behaviour fails it: UBSan does not recover, ASan and UBSan halt on the first report.
#   bash scripts/sanitize.sh [extra ctest args]
set -euo pipefail
cd "$(dirname "$0")/.."
flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Release -DMESHQUILT_PERF=OFF -DMESHQUILT_PYTHON=OFF \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_CXX_FLAGS_RELEASE="-O1 -g1 -DNDEBUG" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
cmake --build build-asan -j"$(nproc)" --target quick_tests
export ASAN_OPTIONS=detect_leaks=1:halt_on_error=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=0
export LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
# The end_to_end and slow executables are not built: their placeholders (NAME_NOT_BUILT) are left out.
ctest --test-dir build-asan --output-on-failure -j"$(nproc)" --timeout 900 -LE 'end_to_end|slow' -E '_NOT_BUILT$' "$@"
