#!/usr/bin/env bash
# README command 1: set up, build, and run the main job headless on lavapipe, writing its
# pictures under out/ and printing their paths.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
./build/apps/smoke/phigs-smoke --output out/smoke.png
