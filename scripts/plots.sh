#!/usr/bin/env bash
# The figures of docs/validation.md, docs/performance.md and the README: each
# hard case run in Impulse2D and in Box2D 2.4.1 with a trace, the traces drawn
# as charts (testbed plot), and the main job's scene rendered side by side.
# Work files go to out/plots/; the summaries land in docs/images/ (reduced to
# a small palette with ImageMagick when it is installed).
#
#   scripts/plots.sh          (after a build: build/testbed/testbed)
set -euo pipefail
cd "$(dirname "$0")/.."
TB=${TESTBED:-build/testbed/testbed}
OUT=out/plots
IMAGES=docs/images
mkdir -p "$OUT" "$IMAGES"

shrink() {  # shrink SRC DEST: a palette PNG when ImageMagick is there, else a copy
  if command -v convert > /dev/null; then convert "$1" -colors 64 "PNG8:$2"; else cp "$1" "$2"; fi
}

# case NAME SCENE SECONDS TITLE [settings options...]
case_plot() {
  local name=$1 scene=$2 seconds=$3 title=$4
  shift 4
  mkdir -p "$OUT/$name"
  for engine in impulse2d box2d; do
    # A run that goes non-finite exits 1; its trace says where it stopped.
    "$TB" run "$scene" --seconds "$seconds" --engine "$engine" "$@" --trace "$OUT/$name/$engine.csv" > /dev/null || true
  done
  "$TB" plot "$OUT/$name/impulse2d.csv" "$OUT/$name/box2d.csv" --title "$title" --size 640x360 \
    --out "$OUT/$name" 2> /dev/null
  shrink "$OUT/$name/summary.png" "$IMAGES/trace_$name.png"
  echo "wrote $IMAGES/trace_$name.png" >&2
}

case_plot column_no_sleep tall_stack20 10 "tall_stack20, sleep off" --sleep off
case_plot heavy_chain heavy_chain 10 "heavy_chain"
case_plot overlap_pile stack5_overlap 5 "stack5_overlap"
case_plot pyramid20 pyramid20 10 "pyramid20"

# The main job's scene, both engines side by side: a contact sheet of 8 frames.
"$TB" render pyramid20 --compare box2d --frames 241 --every 30 --size 480x270 --no-gif --quiet \
  --out "$OUT/pyramid20_compare" 2> /dev/null
shrink "$OUT/pyramid20_compare/sheet.png" "$IMAGES/compare_pyramid20.png"
echo "wrote $IMAGES/compare_pyramid20.png" >&2
