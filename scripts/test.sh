#!/usr/bin/env bash
# Builds coremodal and runs every test (Catch2 through ctest, pytest for python/).
# The test run installs the optional groups of setup.sh too (ParaView for the
# pvpython tests, pandas and meshio), unless COREMODAL_PARAVIEW=0 or
# COREMODAL_EXTRAS=0 is set; without them those tests are skipped.
set -euo pipefail
cd "$(dirname "$0")/.."
COREMODAL_PARAVIEW="${COREMODAL_PARAVIEW:-1}" COREMODAL_EXTRAS="${COREMODAL_EXTRAS:-1}" bash scripts/setup.sh
bash scripts/build.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# ctest starts the longest tests first when it knows their times; a fresh
# checkout has none, and then ran its two longest last, each alone on one core
# (pytest, 166 s; a solid Campbell run, 164 s). tests/ctest_costs.txt is a
# full run's record (build/Testing/Temporary/CTestCostData.txt, entries with
# runs > 0): copy it again after adding long tests.
costs=build/Testing/Temporary/CTestCostData.txt
[ -f "$costs" ] || { mkdir -p "$(dirname "$costs")" && cp tests/ctest_costs.txt "$costs"; }
ctest --test-dir build --output-on-failure -j 2 "$@"
