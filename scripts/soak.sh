#!/usr/bin/env bash
# Soak: an hour of simulated time (or SECONDS) of rain1000, pyramid20 and
# bridge in the Release build, checking for non-finite state and memory
# growth after warm-up (tests/robustness/soak.cpp). Runs the scenes as
# shipped (sleep on) and again with sleep off, so every body is stepped
# every step.
# Usage: scripts/soak.sh [SECONDS (default 3600)]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-3600}
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j 2 --target soak >&2
status=0
for sleep in on off; do
  /usr/bin/time -f "%e s wall, max RSS %M KiB" build/tests/robustness/soak --seconds "$seconds" --sleep "$sleep" \
    rain1000 pyramid20 bridge || status=1
done
exit $status
