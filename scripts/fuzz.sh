#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz/ with clang 14 into build-fuzz/ and runs each for
# SECONDS (default 60) on a working copy of its seed corpus plus the regression files.
#   bash scripts/fuzz.sh [--corpus DIR] [SECONDS] [TARGET...]
# With --corpus, each target's working corpus is DIR/TARGET and is kept between runs (a long
# campaign in several sittings, or a CI cache; DIR relative to the repository); without, it is
# build-fuzz/corpus/TARGET.
# A crash, a sanitizer report or a hang over 10 s stops that target; the input is saved under
# build-fuzz/artifacts/TARGET/ and the script fails. Copy it to tests/fuzz/regressions/TARGET/
# so the normal test suite replays it (fuzz_corpus_test). Prints executions per target.
set -euo pipefail
cd "$(dirname "$0")/.."
corpus_root=build-fuzz/corpus
if [ "${1:-}" = --corpus ]; then
  [ -n "${2:-}" ] || { echo "fuzz.sh: --corpus needs a folder" >&2; exit 2; }
  corpus_root=$(realpath -m "$2")
  shift 2
fi
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(obj ply off stl swatch base netpbm field texture)
jobs=${FUZZ_BUILD_JOBS:-2}

command -v clang++-14 >/dev/null || { echo "fuzz.sh: clang++-14 missing (apt-get install clang-14 libclang-rt-14-dev)" >&2; exit 1; }
# The whole project with clang and the sanitizers, the fuzz targets built over its own library
# targets (no Vulkan: the readers never reach the device).
sanitize="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
CXX=clang++-14 cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DMESHQUILT_FUZZ=ON -DMESHQUILT_TESTS=OFF -DMESHQUILT_PERF=OFF -DMESHQUILT_VULKAN=OFF -DMESHQUILT_PYTHON=OFF \
  -DCMAKE_CXX_FLAGS="$sanitize -fsanitize=fuzzer-no-link" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
# The build's own messages only on failure (a link error must be visible in CI's log).
fuzzers=()
for t in obj ply off stl swatch base netpbm field texture; do fuzzers+=("${t}_fuzzer"); done
if ! cmake --build build-fuzz -j"$jobs" --target "${fuzzers[@]}" >build-fuzz/build.log 2>&1; then
  tail -40 build-fuzz/build.log >&2
  echo "fuzz.sh: building the fuzz targets failed (log: build-fuzz/build.log)" >&2
  exit 1
fi

status=0
total=0
printf '%-8s %12s %8s %8s %s\n' target executions seconds corpus result
for t in "${targets[@]}"; do
  work=$corpus_root/$t
  artifacts=build-fuzz/artifacts/$t/
  mkdir -p "$work" "$artifacts"
  cp -n tests/fuzz/corpus/"$t"/* "$work"/ 2>/dev/null || true
  [ -d tests/fuzz/regressions/"$t" ] && cp -n tests/fuzz/regressions/"$t"/* "$work"/ 2>/dev/null || true
  log=build-fuzz/$t.log
  result=ok
  # UBSan reports end the run (fuzz targets are built with -fno-sanitize-recover=all).
  if ! UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ./build-fuzz/"$t"_fuzzer "$work" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
      -artifact_prefix="$artifacts" -print_final_stats=1 >"$log" 2>&1; then
    result="FAILED (see $log, input in $artifacts)"
    status=1
  fi
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  total=$((total + ${runs:-0}))
  printf '%-8s %12s %8s %8s %s\n' "$t" "${runs:-0}" "$seconds" "$(find "$work" -type f | wc -l)" "$result"
done
printf '%-8s %12s\n' total "$total"
exit $status
