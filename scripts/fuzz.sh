#!/usr/bin/env bash
# Builds the case-file fuzzer (fuzz/, libFuzzer + AddressSanitizer +
# UndefinedBehaviorSanitizer, with clang) in build-fuzz/ and runs it.
#
#   bash scripts/fuzz.sh                 # 120 s (CI)
#   bash scripts/fuzz.sh 1800            # 30 minutes
#   bash scripts/fuzz.sh 0 -runs=1000000 # a number of inputs instead of a time
#
# Seeds: every case in cases/ and cases/hard/ and every kept crash in
# tests/fuzz_regressions/; the corpus grows in build-fuzz/corpus/ and is kept
# between runs. A crash stops the run with its input in build-fuzz/crashes/;
# replay it with `build-fuzz/case_fuzzer FILE`, fix it, and keep the input in
# tests/fuzz_regressions/ (its test replays every file there).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-120}
shift || true
bash scripts/setup.sh clang libclang-rt-14-dev

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S fuzz -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo "${launcher[@]}" \
  > build-fuzz.log 2>&1 || { cat build-fuzz.log; exit 1; }
cmake --build build-fuzz -j "$(nproc)" 2>&1 | tail -n 5

# The dictionary: TOML syntax (fuzz/case.dict), then every word of the readers
# (case files, winder files, selection files: keys, value choices) and every
# ASCII unit symbol.
{
  cat fuzz/case.dict
  grep -ohE '"[A-Za-z_][A-Za-z0-9_]*"' src/scene/*.cpp src/winder/winder_scene.cpp src/selection/selection_scene.cpp | sort -u
  grep -ohE 'UnitSpec\{"[ -~]+",' src/scene/units.cpp | sed -E 's/UnitSpec\{"(.*)",/" \1"/'
} > build-fuzz/case.dict

mkdir -p build-fuzz/corpus build-fuzz/crashes
rm -f build-fuzz/crashes/*  # a crash left by an earlier run is not this run's
seeds=(cases)
compgen -G "tests/fuzz_regressions/*" >/dev/null && seeds+=(tests/fuzz_regressions)
limit=()
[ "$seconds" -gt 0 ] && limit=(-max_total_time="$seconds")
# -timeout: an input that takes 30 s is a hang (a valid case takes
# milliseconds at the beam level, a winder file up to 1 s; at 10 s a fuzzer
# starved by other work once called a 1 s input a hang, docs/validation/reliability.md);
# -max_len: case files are a few kB.
set +e
build-fuzz/case_fuzzer build-fuzz/corpus "${seeds[@]}" -dict=build-fuzz/case.dict \
  -artifact_prefix=build-fuzz/crashes/ -timeout=30 -max_len=8192 -print_final_stats=1 \
  "${limit[@]}" "$@" 2>&1 | tee build-fuzz/last-run.log |
  grep --line-buffered -E "^(#[0-9]+ *(INITED|DONE|pulse)|Done |stat::|==[0-9]+==|SUMMARY|artifact_prefix|Test unit written|.*deadly signal)"
status=${PIPESTATUS[0]}
set -e
if compgen -G "build-fuzz/crashes/*" >/dev/null; then
  echo "fuzz: the fuzzer found a bug (log: build-fuzz/last-run.log); its input is in build-fuzz/crashes/" >&2
  exit 1
elif [ "$status" -ne 0 ]; then
  echo "fuzz: the fuzzer stopped with status $status but kept no input (interrupted?); log: build-fuzz/last-run.log" >&2
  exit 1
fi
