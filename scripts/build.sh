#!/usr/bin/env bash
# Installs what is missing, then configures and builds coremodal in build/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# ccache, where installed, lets several checkouts share object files.
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# COREMODAL_UNITY_BUILD=OFF compiles src/ file by file (CMakeLists.txt: an
# edit then recompiles one file, not its batch of eight).
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCOREMODAL_UNITY_BUILD="${COREMODAL_UNITY_BUILD:-ON}" "${launcher[@]}" \
  > build.log 2>&1 || { cat build.log; exit 1; }
cmake --build build -j "$(nproc)" 2>&1 | tail -n 20
