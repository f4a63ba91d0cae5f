#!/usr/bin/env bash
# Speed against error: runs the sweep (Impulse2D across its solver settings,
# Box2D 2.4.1 across its iteration counts, on the benchmark scenes), the
# scaling on 1 and 2 workers, the stage-by-stage profile, the memory and
# idle-body figures, draws docs/images/perf_*.png with gnuplot and rewrites
# the generated part of docs/performance.md (between its generated:begin and
# generated:end markers; the rest is kept).
#
# Usage: scripts/performance.sh [--quick] [extra sweep arguments]
#   --quick   a few points, one repeat, short runs (under 3 minutes; for development)
# Builds what is missing in build/ (Release). Data files go to build/perf/.
set -euo pipefail
cd "$(dirname "$0")/.."

for tool in cmake gnuplot; do
  command -v "$tool" >/dev/null || { echo "performance.sh: $tool is missing (scripts/setup.sh installs it)" >&2; exit 1; }
done

if [ ! -f build/CMakeCache.txt ]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
if ! grep -q '^CMAKE_BUILD_TYPE:STRING=Release$' build/CMakeCache.txt; then
  echo "performance.sh: build/ is not a Release build; timing figures need one" >&2
  exit 1
fi
cmake --build build -j 2 --target sweep >&2

out=build/perf
mkdir -p "$out" docs/images
# The revision measured, named in the report (so that two reports, before and
# after a change, say which is which).
revision=()
if rev=$(git describe --always --dirty 2>/dev/null); then
  revision=(--revision "$rev")
fi
build/tests/benchmark/sweep --out "$out" --images docs/images --assets assets "${revision[@]}" "$@"
gnuplot "$out/plots.gp"

doc=docs/performance.md
begin='<!-- generated:begin -->'
end='<!-- generated:end -->'
if ! grep -qF "$begin" "$doc" || ! grep -qF "$end" "$doc"; then
  printf '\n%s\n%s\n' "$begin" "$end" >>"$doc"
fi
# Keep everything outside the markers; put generated.md between them.
awk -v gen="$out/generated.md" -v b="$begin" -v e="$end" '
  $0 == b { print; while ((getline line < gen) > 0) print line; skip = 1; next }
  $0 == e { skip = 0 }
  !skip { print }
' "$doc" >"$doc.tmp"
mv "$doc.tmp" "$doc"
echo "performance.sh: wrote $doc and docs/images/perf_*.png" >&2
