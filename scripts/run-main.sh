#!/usr/bin/env bash
# The main job: set up, build, render pyramid20 to PNG frames, a contact sheet
# and an animation in out/pyramid20/, render it in Impulse2D and Box2D 2.4.1
# side by side in out/pyramid20_compare/, trace both engines and plot the
# traces in out/pyramid20/plots/, and print the scene's figures as JSON.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
TB=build/testbed/testbed
$TB render pyramid20 --frames 240 --every 4 --out out/pyramid20 --size 1280x720
$TB render pyramid20 --compare box2d --frames 240 --every 4 --out out/pyramid20_compare --size 960x540
$TB run pyramid20 --seconds 10 --engine box2d --trace out/pyramid20/trace_box2d.csv > /dev/null
$TB run pyramid20 --seconds 10 --json --trace out/pyramid20/trace_impulse2d.csv
$TB plot out/pyramid20/trace_impulse2d.csv out/pyramid20/trace_box2d.csv --out out/pyramid20/plots
