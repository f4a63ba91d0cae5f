#!/usr/bin/env bash
# Every test: set up, build, run the whole CTest suite.
# With --sanitize, afterwards also build the preset "asan" (AddressSanitizer,
# UndefinedBehaviorSanitizer, LeakSanitizer) in build-asan/ and run every
# test there (opt-in: it adds a second full build, see docs/robustness.md).
set -euo pipefail
cd "$(dirname "$0")/.."
sanitize=0
[ "${1:-}" = "--sanitize" ] && sanitize=1
scripts/setup.sh
jobs=$(nproc 2>/dev/null || echo 2)
ctest --test-dir build --output-on-failure -j "$jobs"
if [ $sanitize = 1 ]; then
  cmake --preset asan >/dev/null
  cmake --build --preset asan >&2
  ctest --preset asan
fi
