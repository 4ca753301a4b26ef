#!/usr/bin/env bash
# Builds coremodal with AddressSanitizer + UndefinedBehaviorSanitizer (clang,
# Debug, -DCOREMODAL_SANITIZE=ON) in build-asan/ and runs the unit and
# verification tests under them (docs/validation.md, "Reliability").
#
#   bash scripts/sanitize.sh            # the CI selection below
#   bash scripts/sanitize.sh all        # every unit and verification test
#   bash scripts/sanitize.sh "[beam]"   # any Catch2 test spec instead
#
# Any report fails the run: ASan stops at the first invalid access, and
# -fno-sanitize-recover makes undefined behaviour fatal too.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh clang libclang-rt-14-dev

# Leak checking: Open MPI and PETSc keep memory until exit by design (MPI's
# own tables, PETSc's registries); the suppressions name those libraries only,
# so a leak in coremodal's code is still reported.
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"
# Open MPI's memory hooks fight ASan's allocator: switch them off. Its plugins
# (mca_*.so) stay loaded at exit, so that their allocations are named by
# library (an unloaded plugin's leak shows as "<unknown module>").
export OMPI_MCA_memory=^patcher OMPI_MCA_mca_base_component_disable_dlclose=1
# fast_unwind_on_malloc=0: full allocation stacks through libraries built
# without frame pointers (vasprintf inside Open MPI), so that the suppressions
# can match them.
export ASAN_OPTIONS="abort_on_error=0:halt_on_error=1:detect_stack_use_after_return=0:fast_unwind_on_malloc=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# The environment above is set before building: the build runs the test
# binary once to list its tests (catch_discover_tests).
# -g1 writes the build folder into the objects, and ccache hashes it: without
# this, a second checkout (a work tree, CI's clone) recompiles everything.
export CCACHE_NOHASHDIR=1
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# -O0 -g1 (line tables only, enough for the reports' stacks): compiling with
# the sanitizers costs 1.1-1.5x a Release build at -O0 -g1 but 3.7-5.8x at
# -O1 -g (measured on run_case.cpp and element.cpp), and a fresh CI machine
# compiles everything. clang, not gcc: it compiles a test file in 0.55 of
# gcc's time with the same flags (test_harmonic_level.cpp, measured side by
# side), and its sanitizers are the reference ones (the fuzzer's too).
# A tree configured with another compiler is configured afresh.
if [ -f build-asan/CMakeCache.txt ] && ! grep -q "CMAKE_CXX_COMPILER:.*clang++" build-asan/CMakeCache.txt; then
  rm -rf build-asan
fi
cmake -S . -B build-asan -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O0 -g1" \
  -DCOREMODAL_SANITIZE=ON "${launcher[@]}" \
  > build-asan.log 2>&1 || { cat build-asan.log; exit 1; }
cmake --build build-asan -j "$(nproc)" 2>&1 | tail -n 5

# The selection: every unit test and the verification tests on small
# scenes (tube: the solid level's solves; chucks; harmonic), not the example
# cases, the hard cases or the app tests (the same code on larger meshes, or
# the program as a child process), nor the converge ladders (their repeat
# counts depend on speed, which -O0 under ASan does not have). CI leaves out
# the tests tagged [long] too: each took 30 s to 4 min at -O0 under the
# sanitizers on a loaded machine (solid meshes with chucks, harmonic sensitivities, dense
# response sweeps) and runs the same code as the quicker tests beside it;
# `all` runs them. Its time and status: docs/validation.md, "Reliability".
everything="~[app]~[hard]~[cases]~[e2e]~[beam_vs_solid]~[converge]"
case "${1:-ci}" in
  ci) spec="$everything~[long]" cap=1200 ;;
  all) spec="$everything" cap=3600 ;;
  *) spec="$1" cap=3600 ;;
esac
# Capped: a selection grown too slow fails here instead of overrunning CI's budget.
time timeout "$cap" build-asan/tests/coremodal_tests "$spec" --durations yes > build-asan/tests.log 2>&1 || {
  tail -n 80 build-asan/tests.log
  echo "sanitize: tests failed or a sanitizer reported (build-asan/tests.log)" >&2
  exit 1
}
tail -n 3 build-asan/tests.log
