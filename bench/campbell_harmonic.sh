#!/usr/bin/env bash
# The 41-speed Campbell diagram of cases 07 and 08 at the harmonic level
# (bench/results/log.md, "Campbell sweeps at the harmonic level").
# Cases 07 and 08 have no [rotation] table: this script copies them into a
# temporary folder with one added (0 ... 3000 rpm, 41 speeds, orders 1 and 2)
# and times `coremodal campbell --model harmonic --no-plots` on each,
# REPEATS times (default 3), printing every run's wall and CPU (user + sys)
# seconds and their medians.
#
#   bash bench/campbell_harmonic.sh [REPEATS] [extra coremodal options]
#
# ROTATION_EXTRA adds lines to the [rotation] table, e.g.
#   ROTATION_EXTRA='centrifugal_stiffening = false' bash bench/campbell_harmonic.sh 3
# and OUT_TAG names the copies of campbell.csv and critical_speeds.csv left
# in /tmp (default: none), to compare two builds' answers.
set -euo pipefail
cd "$(dirname "$0")/.."
repeats=${1:-3}
shift || true
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for case in cases/07-*.toml cases/08-*.toml; do
    name=$(basename "$case" .toml)
    { cat "$case"; printf '\n[rotation]\nspeeds = ["0 rpm", "3000 rpm"]\npoints = 41\nexcitation_orders = [1, 2]\n%s\n' "${ROTATION_EXTRA:-}"; } \
        > "$work/$name.toml"
    walls=() cpus=()
    for ((r = 1; r <= repeats; ++r)); do
        /usr/bin/time -f "%e %U %S" -o "$work/time" \
            ./build/coremodal campbell "$work/$name.toml" --model harmonic --no-plots \
            --output "$work/$name-out" --force "$@" > "$work/log" 2>&1 || { cat "$work/log"; exit 1; }
        read -r wall user sys < "$work/time"
        cpu=$(echo "$user + $sys" | bc)
        walls+=("$wall") cpus+=("$cpu")
        echo "$name run $r: wall ${wall} s, cpu ${cpu} s"
    done
    head -n 8 "$work/log"
    median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }
    echo "$name: median of $repeats: wall $(median "${walls[@]}") s, cpu $(median "${cpus[@]}") s"
    cp "$work/$name-out/critical_speeds.csv" "/tmp/${name}${OUT_TAG:+-$OUT_TAG}-critical_speeds.csv" 2>/dev/null || true
    cp "$work/$name-out/campbell.csv" "/tmp/${name}${OUT_TAG:+-$OUT_TAG}-campbell.csv" 2>/dev/null || true
done
