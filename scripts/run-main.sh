#!/usr/bin/env bash
# The main job: set up, build, render pyramid20 to PNG frames, a contact sheet
# and an animation in out/pyramid20/, and print the scene's figures as JSON.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
build/testbed/testbed render pyramid20 --frames 240 --every 4 --out out/pyramid20 --size 1280x720
build/testbed/testbed run pyramid20 --seconds 10 --json
