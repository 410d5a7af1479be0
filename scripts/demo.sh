#!/usr/bin/env bash
# README command 1: set up, build, and run the main job headless on lavapipe: the ACSYNT demo
# session (apps/acsynt/data/demo.session) replayed, writing its four-view pictures and a text
# summary under out/ (and a PDF of the mapped logo's views) and printing their paths.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
./build/apps/acsynt/acsynt --script apps/acsynt/data/demo.session --output out/
