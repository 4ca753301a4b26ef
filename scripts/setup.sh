#!/usr/bin/env bash
# Installs every Debian package coremodal needs, if any is missing. Idempotent:
# a machine that has them all is left alone (no apt-get update).
#
# Optional groups, installed only when asked for:
#   COREMODAL_PARAVIEW=1  ParaView, its python (pvpython) and a virtual display:
#                         python/coremodal/paraview_mode.py and its tests
#                         (skipped without them). About 140 packages, 84 MB to
#                         download, 806 MB installed; 1-6 min.
#   COREMODAL_BENCH=1     CalculiX (ccx), for bench/calculix_compare.py
#                         (docs/performance.md "Against CalculiX").
#   COREMODAL_EXTRAS=1    pandas and meshio for Results.to_pandas/to_meshio
#                         and their tests (skipped without them); 41 MB.
#
# Extra package names as arguments are installed the same way (scripts/fuzz.sh: clang).
set -euo pipefail
packages=(build-essential cmake pkg-config
          petsc-dev slepc-dev libsuitesparse-dev libopenblas0-pthread
          libgmsh-dev gmsh libhdf5-openmpi-dev libeigen3-dev
          catch2 libtomlplusplus-dev libcli11-dev nlohmann-json3-dev
          libboost-dev
          libmumps-dev  # libsmumps: the single-precision factor (eigensolve/single_factor.cpp)
          python3 python3-h5py python3-numpy python3-matplotlib python3-pytest
          python3-pil python3-pip python3-setuptools python3-venv
          python3-jsonschema  # python/tests/test_case_schema.py
          chromium "$@")  # headless, opens report.html in python/tests/test_report_html.py (about 100 MB)
if [ "${COREMODAL_PARAVIEW:-0}" = 1 ]; then
  packages+=(paraview python3-paraview xvfb)
fi
if [ "${COREMODAL_BENCH:-0}" = 1 ]; then
  packages+=(calculix-ccx)
fi
if [ "${COREMODAL_EXTRAS:-0}" = 1 ]; then
  packages+=(python3-pandas python3-meshio)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
