#!/usr/bin/env bash
# Every test: set up, build with warnings as errors, run the whole CTest
# suite, then build the engine's tests under AddressSanitizer,
# UndefinedBehaviorSanitizer and LeakSanitizer (preset "asan-engine",
# build-asan-engine/) and run them (docs/robustness.md, "Sanitizers").
#   --sanitize   afterwards also build every target under the sanitizers
#                (preset "asan", build-asan/) and run every test there: a
#                second full build, opt-in
#   --no-asan    skip the sanitizer stage of the engine's tests (a quicker
#                local run; CI runs it)
#   --tsan       afterwards also build the testbed's tests under
#                ThreadSanitizer (preset "tsan", build-tsan/) and run the
#                determinism tests, which step worlds on several workers
set -euo pipefail
cd "$(dirname "$0")/.."
sanitize=0
engine_asan=1
tsan=0
for arg in "$@"; do
  case "$arg" in
    --sanitize) sanitize=1 ;;
    --no-asan) engine_asan=0 ;;
    --tsan) tsan=1 ;;
    *) echo "usage: scripts/run-tests.sh [--sanitize] [--no-asan] [--tsan]" >&2; exit 2 ;;
  esac
done
scripts/setup.sh -DI2D_WERROR=ON
jobs=$(nproc 2>/dev/null || echo 2)
ctest --test-dir build --output-on-failure -j "$jobs"
if [ $engine_asan = 1 ]; then
  cmake --preset asan-engine -DI2D_WERROR=ON >/dev/null
  cmake --build --preset asan-engine >&2
  ctest --preset asan-engine
fi
if [ $sanitize = 1 ]; then
  cmake --preset asan -DI2D_WERROR=ON >/dev/null
  cmake --build --preset asan >&2
  ctest --preset asan
fi
if [ $tsan = 1 ]; then
  cmake --preset tsan -DI2D_WERROR=ON >/dev/null
  cmake --build --preset tsan >&2
  ctest --preset tsan
fi
