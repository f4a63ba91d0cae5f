#!/usr/bin/env bash
# Regenerate docs/validation.md: every validation case (tests/validation/cases.cpp,
# joint_cases.cpp)
# run in Impulse2D and in Box2D 2.4.1, side by side with the analytic answers.
# Usage: scripts/validate.sh [build dir, default build]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
jobs=$(nproc 2>/dev/null || echo 2)
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" -j "$jobs" --target validation_report >&2
"$build/tests/validation/validation_report" --out docs/validation.md
