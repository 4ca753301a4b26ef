#!/usr/bin/env bash
# Every shipped solid case with the one factor in single and in double
# precision (issue 39): `coremodal run CASE --model solid -factor_precision
# double|single`, alternating, one process. Prints one row a case: the
# precision each run used (summary.json's verification.factor_precision),
# the largest relative difference of the frequencies, whether both proved
# their modes complete, where the count came from, and the CPU (user + sys)
# medians of the alternating runs with the load average (timings on a shared
# machine are noisy: compare CPU, not wall).
#
#   bash bench/single_vs_double.sh [MESH] [REPEATS] [CASE.toml ...]
#
# MESH: the mesh level for every generated mesh (default coarse; "shipped"
# for the case's own; a [mesh] file is always its own), REPEATS: alternating pairs per case (default 1). Without
# cases: every case under cases/, cases/hard and cases/validation whose
# model resolves to the solid level (`coremodal check`). COREMODAL names the
# binary (default build/coremodal). Exits non-zero when a case's frequencies
# differ by more than 1e-9 or a run is not proven complete.
set -euo pipefail
cd "$(dirname "$0")/.."
mesh=${1:-coarse}
repeats=${2:-1}
shift $(($# < 2 ? $# : 2))
bin=${COREMODAL:-build/coremodal}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cases=("$@")
if [ ${#cases[@]} -eq 0 ]; then
    for f in cases/*.toml cases/hard/*.toml cases/validation/*.toml; do
        # A plain run of the solid level: not a study, limits, selection or traction case.
        grep -qE '^\[(study|selection|traction|winder)\]|^\[\[measurement\]\]' "$f" && continue
        "$bin" check "$f" 2>/dev/null | grep -q "model level: solid" && cases+=("$f")
    done
fi

# One run: CPU seconds (user + sys) into $work/<tag>.cpu, summary.json kept.
# A case on its own mesh file ([mesh] file) runs on it whatever MESH says.
run_one() {
    local case_file=$1 precision=$2 tag=$3
    local mesh_args=()
    [ "$mesh" != shipped ] && ! grep -qE '^file *=' "$case_file" && mesh_args=(--mesh "$mesh")
    /usr/bin/time -f "%U %S" -o "$work/$tag.time" "$bin" run "$case_file" --model solid "${mesh_args[@]}" -q \
        --no-plots --force -o "$work/$tag" -factor_precision "$precision" >"$work/$tag.log" 2>&1 || {
        echo "run failed: $case_file -factor_precision $precision ($work/$tag.log):" >&2
        tail -5 "$work/$tag.log" >&2
        return 1
    }
    awk '{print $1 + $2}' "$work/$tag.time" >>"$work/$precision.cpu"
}

printf '| case | DOFs | modes | used (double run / single run) | max rel. freq. difference | complete (d/s) | count of the single run | CPU median double / single [s] | load |\n'
printf '|---|---|---|---|---|---|---|---|---|\n'
status=0
for c in "${cases[@]}"; do
    rm -f "$work"/*.cpu
    load_before=$(cut -d' ' -f1 /proc/loadavg)
    for ((i = 0; i < repeats; ++i)); do
        run_one "$c" double "d$i" || { status=1; continue 2; }
        run_one "$c" single "s$i" || { status=1; continue 2; }
    done
    load_after=$(cut -d' ' -f1 /proc/loadavg)
    python3 - "$c" "$work/d0/summary.json" "$work/s0/summary.json" "$work/double.cpu" "$work/single.cpu" \
        "$load_before" "$load_after" <<'EOF' || status=1
import json, statistics, sys
case, dpath, spath, dcpu, scpu, lb, la = sys.argv[1:]
d, s = json.load(open(dpath)), json.load(open(spath))
fd = [m["frequency_hz"] for m in d["modes"]]
fs = [m["frequency_hz"] for m in s["modes"]]
def used(run):
    p = run["verification"].get("factor_precision")
    return p["used"] if p else "(no one factor)"
def cpu(path):
    return statistics.median(float(x) for x in open(path))
if len(fd) != len(fs):
    diff, text = float("inf"), f"{len(fd)} vs {len(fs)} modes"
else:
    # Rigid modes (a free body's, near 0 Hz) against the highest frequency: their own is round-off's.
    floor = 1e-6 * max(map(abs, fd), default=1.0)
    diff = max((abs(a - b) / max(abs(a), floor) for a, b in zip(fd, fs)), default=0.0)
    text = f"{diff:.1e}"
sp = s["verification"].get("factor_precision")
count = sp["count"].split(":")[0] if sp else "(no one factor)"
if sp and "fell back" in sp["count"]:
    count = sp["count"]
vd, vs = d["verification"]["complete"], s["verification"]["complete"]
print(f"| {case} | {d['model']['n_dofs']} | {len(fd)} | {used(d)} / {used(s)} | {text} | {vd} / {vs} | {count} | "
      f"{cpu(dcpu):.1f} / {cpu(scpu):.1f} | {lb}–{la} |")
sys.exit(0 if diff <= 1e-9 and vd and vs else 1)
EOF
done
exit $status
