#!/usr/bin/env bash
# Builds coremodal with AddressSanitizer + UndefinedBehaviorSanitizer (clang,
# Debug, -DCOREMODAL_SANITIZE=ON) in build-asan/ and runs the unit and
# verification tests under them (docs/validation/reliability.md, "Reliability").
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
# Hidden tests ([.]: measurements for the docs, minutes long) are never in the selection.
# Two passes. Memory errors and undefined behaviour over the whole selection,
# with leak checking off: it needs every allocation's full stack
# (fast_unwind_on_malloc=0, to see past libraries without frame pointers into
# Open MPI, which the suppressions name), and that unwinding made the solver
# tests 5 to 25 times slower (perf: libgcc's unwinder and the kernel; a chuck
# test 60 s against 2.3 s). Then leaks, with full stacks, over the tests of
# coremodal's own containers and writers (the `leaks` spec below).
memory_options="abort_on_error=0:halt_on_error=1:detect_stack_use_after_return=0"
export ASAN_OPTIONS="$memory_options:detect_leaks=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# One BLAS thread per shard, as ctest's environment (tests/CMakeLists.txt):
# the shards already fill the cores, and a second thread only spins.
export OPENBLAS_NUM_THREADS=1

# The environment above is set before building: the build runs the test
# binary once to list its tests (catch_discover_tests).
# -g1 writes the build folder into the objects, and ccache hashes it: without
# this, a second checkout (a work tree, CI's clone) recompiles everything.
export CCACHE_NOHASHDIR=1
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# -O1 -g1 (line tables only, enough for the reports' stacks): -O1 compiles
# in 1.4-1.5x -O0's time (element.cpp, measured twice side by side) and runs
# the solver tests 2 to 10 times faster (Eigen's fixed-size kernels are not
# inlined at -O0: a chuck test 38 s against 77 s, the dense beam and response
# tests more), which pays for it on a fresh CI machine that compiles
# everything. clang, not gcc: it compiles a test file in 0.55 of gcc's time
# with the same flags (test_harmonic_level.cpp, measured side by side), and
# its sanitizers are the reference ones (the fuzzer's too).
# A tree configured with another compiler is configured afresh.
if [ -f build-asan/CMakeCache.txt ] && ! grep -q "CMAKE_CXX_COMPILER:.*clang++" build-asan/CMakeCache.txt; then
  rm -rf build-asan
fi
# Precompiled headers (the standard library, Eigen, Catch2): 0.74 of the
# compile CPU on 24 files drawn at random (144.4 s against 106.8 s, session
# 22, CMakeLists.txt's COREMODAL_PRECOMPILED_HEADERS); ccache caches such
# compiles only with the sloppiness below.
export CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
cmake -S . -B build-asan -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" \
  -DCOREMODAL_SANITIZE=ON -DCOREMODAL_PRECOMPILED_HEADERS=ON "${launcher[@]}" \
  > build-asan.log 2>&1 || { cat build-asan.log; exit 1; }
cmake --build build-asan -j "$(nproc)" 2>&1 | tail -n 5

# The selection: every unit test and the verification tests on small
# scenes (tube: the solid level's solves; chucks; harmonic), not the example
# cases, the hard cases or the app tests (the same code on larger meshes, or
# the program as a child process), nor the converge ladders (their repeat
# counts depend on speed, which -O0 under ASan does not have). CI leaves out
# the tests tagged [long] too: each took over 20 s under the sanitizers
# (solid meshes with chucks, harmonic sensitivities, dense response sweeps,
# rotating-frame pencils, the coupled contact's comparisons with the solid)
# and runs the same code as a quicker test beside it; `all` runs them. In
# session 14 the 19 slowest of run 11 (857 s of its 1,282 s in two shards)
# were tagged so, to keep CI under 40 minutes. Its time and status:
# docs/validation/reliability.md, "Reliability".
everything="~[.]~[app]~[hard]~[cases]~[e2e]~[beam_vs_solid]~[converge]"
# The leak pass: the tests of coremodal's own containers, readers and writers.
leak_tags=(scene output element material mesh modes mac numerics geometry tracking results_folder study)
leaks=""
for t in "${leak_tags[@]}"; do leaks+="${leaks:+,}[$t]$everything~[long]"; done
case "${1:-ci}" in
  ci) spec="$everything~[long]" cap=1200 ;;
  all) spec="$everything" cap=3600 ;;
  *) spec="$1" cap=3600 leaks="" ;;
esac
# The selection runs as one process per core (Catch2 2 has no sharding):
# its test names, escaped for a Catch2 test spec (\ , [ * " and a leading ~
# are special there), dealt out in turn to the shards so that the slow
# verification tests at the end of the list are shared too. Tests already
# run side by side under ctest -j, so they do not share files.
shards=$(nproc)
# (Catch2 2's --list-test-names-only exits with the number of tests listed.)
{ build-asan/tests/coremodal_tests --list-test-names-only "$spec" || true; } | grep -v '^$' |
  sed -e 's/\\/\\\\/g' -e 's/[],[*"]/\\&/g' -e 's/^~/\\~/' > build-asan/selection.txt || true
if [ ! -s build-asan/selection.txt ]; then
  echo "sanitize: no test matches '$spec' (or the test program does not start)" >&2
  exit 1
fi
for ((i = 0; i < shards; ++i)); do
  awk -v n="$shards" -v i="$i" 'NR % n == i' build-asan/selection.txt > "build-asan/shard-$i.txt"
done
echo "sanitize: $(wc -l < build-asan/selection.txt) test cases in $shards processes"
# Capped: a selection grown too slow fails here instead of overrunning CI's budget.
started=$SECONDS
pids=()
for ((i = 0; i < shards; ++i)); do
  timeout "$cap" build-asan/tests/coremodal_tests -f "build-asan/shard-$i.txt" --durations yes \
    > "build-asan/tests-$i.log" 2>&1 &
  pids+=($!)
done
failed=()
for ((i = 0; i < shards; ++i)); do
  wait "${pids[$i]}" || failed+=("$i")
done
echo "sanitize: tests ran in $((SECONDS - started)) s"
for i in "${failed[@]}"; do
  tail -n 80 "build-asan/tests-$i.log"
  echo "sanitize: shard $i failed, was stopped by the ${cap} s cap, or a sanitizer reported (build-asan/tests-$i.log)" >&2
done
[ "${#failed[@]}" -eq 0 ] || exit 1
for ((i = 0; i < shards; ++i)); do tail -n 3 "build-asan/tests-$i.log"; done

# Leaks, with every allocation's full stack (see ASAN_OPTIONS above).
if [ -n "$leaks" ]; then
  started=$SECONDS
  ASAN_OPTIONS="$memory_options:detect_leaks=1:fast_unwind_on_malloc=0" \
    timeout "$cap" build-asan/tests/coremodal_tests "$leaks" > build-asan/leaks.log 2>&1 || {
    tail -n 80 build-asan/leaks.log
    echo "sanitize: the leak pass failed, was stopped by the ${cap} s cap, or LeakSanitizer reported (build-asan/leaks.log)" >&2
    exit 1
  }
  echo "sanitize: leak pass in $((SECONDS - started)) s: $(grep -E '^(All tests passed|test cases)' build-asan/leaks.log | tail -n 1)"
fi
