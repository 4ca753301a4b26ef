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
# tests/test_costs.cmake gives the long tests a COST, so that ctest -j starts
# them first (scripts/record_test_costs.sh writes it).
ctest --test-dir build --output-on-failure -j 2 "$@"
