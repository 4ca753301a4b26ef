#!/usr/bin/env bash
# Builds coremodal and runs the main job on a shipped example case
# (default: the 76x15 mm core clamped over 70 mm at each end).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
./build/coremodal run "${1:-cases/02-clamped-76x15.toml}"
