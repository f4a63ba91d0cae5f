#!/usr/bin/env bash
# Builds the libFuzzer targets (preset "fuzz": clang, ASan + UBSan) and runs
# each for a given time, starting from its seed corpus in tests/fuzz/corpus/.
# New inputs go to build-fuzz/corpus/NAME; a failing input is saved as
# build-fuzz/artifacts/NAME-crash-* (copy it into tests/fuzz/corpus/NAME once
# fixed, so that the default test run replays it).
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET (default 60)] [TARGET...]
#        targets: scene_loader hull collide impact world chain (default: all)
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(scene_loader hull collide impact world chain)

cmake --preset fuzz >/dev/null
cmake --build --preset fuzz >&2

mkdir -p build-fuzz/artifacts
status=0
for t in "${targets[@]}"; do
  mkdir -p "build-fuzz/corpus/$t"
  echo "== fuzz_$t for ${seconds}s" >&2
  if ! ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
      "build-fuzz/tests/fuzz/fuzz_$t" "build-fuzz/corpus/$t" "tests/fuzz/corpus/$t" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
      -artifact_prefix="build-fuzz/artifacts/$t-" 2> "build-fuzz/fuzz_$t.log"; then
    echo "fuzz_$t FAILED: see build-fuzz/fuzz_$t.log and build-fuzz/artifacts/" >&2
    status=1
  fi
  grep -E "stat::number_of_executed_units|stat::new_units_added|^#[0-9]+ +DONE" "build-fuzz/fuzz_$t.log" >&2 || true
done
exit $status
