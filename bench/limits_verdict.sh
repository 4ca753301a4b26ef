#!/usr/bin/env bash
# The verdict over the unwind (`coremodal limits`, bench/results/log.md, "The
# verdict over the unwind"): case 16 (case 07's roll and stand with 40 mm of
# rest paper, 20 rest-roll diameters down to the bare core, every criterion
# and the band) at the beam level and at the harmonic level, REPEATS times
# each (default 3), printing every run's wall and CPU (user + sys) seconds
# and their medians. CPU is the number to compare on a shared machine.
#
#   bash bench/limits_verdict.sh [REPEATS] [extra coremodal options]
#
# LEVELS chooses the levels (default "beam harmonic"), CASES the case files
# (default case 16; case 17 is the news stand). The coupled level (segmented
# chucks: f1, k, I-5, Koenig coupled; the spinning criteria from the
# axisymmetric equivalent's harmonic level; bench/results/log.md, "fifth
# pass"):
#   CASES=cases/17-limits-news-segmented-76x15-2200.toml LEVELS=coupled bash bench/limits_verdict.sh 3
# Targets (issue 36): beam <= 2 s, harmonic <= 30 s, coupled <= 2 min CPU.
set -euo pipefail
cd "$(dirname "$0")/.."
repeats=${1:-3}
shift || true
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# The machine (the numbers are its own; docs/performance.md says which).
echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)"
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }
for case in ${CASES:-cases/16-limits-rotogravure-150x15.8-4320.toml}; do
for level in ${LEVELS:-beam harmonic}; do
    walls=() cpus=()
    for ((r = 1; r <= repeats; ++r)); do
        /usr/bin/time -f "%e %U %S" -o "$work/time" \
            ./build/coremodal limits "$case" --model "$level" --no-plots --output "$work/out-$level" --force "$@" \
            > "$work/log" 2>&1 || { cat "$work/log"; exit 1; }
        read -r wall user sys < "$work/time"
        cpu=$(echo "$user + $sys" | bc)
        walls+=("$wall") cpus+=("$cpu")
        echo "$(basename "$case") $level run $r: wall ${wall} s, cpu ${cpu} s"
    done
    tail -n 1 "$work/log"
    echo "$(basename "$case") $level: median of $repeats: wall $(median "${walls[@]}") s, cpu $(median "${cpus[@]}") s"
done
done
