#!/usr/bin/env bash
# Failure injection (issue 33): coremodal under what a hostile but realistic
# machine does to it, one row per trial and a total.
#
#   scripts/failure_injection.sh [--ci | --quick] [--no-mount] [--keep] [BINARY]
#
# Trials: a full disk (a small tmpfs; skipped with the reason where mount is
# not allowed), memory limits (ulimit -v), every signal (INT, TERM, HUP,
# QUIT, PIPE) at three moments (start, solve, write) and a reader that goes
# away (`run ... | head -2`), two runs into one --output at once, and every
# command under `mpirun -n 2`. Each trial has a user's sentinel file beside
# its output and, where the command writes a folder, an earlier result in it.
#
# Each trial is one of
#   ok      the command did what was asked (exit 0, its folder complete)
#   clear   it stopped with a clear message and a non-zero exit, nothing
#           half-written left (or, for a signal, exited 128 + signal quietly)
#   crash   a crash or a raw dump: an exit by an uncaught signal or abort, a
#           PETSc "Caught signal" dump, `terminate called`, exit 59, a
#           partial folder or an orphaned child left behind
#   hang    no end within the trial's time limit (then killed)
#   lost    the sentinel or the earlier result changed or missing (an
#           earlier result may only have moved to <out>.previous)
# The exit status is 1 when any trial crashed, hung or lost data.
#
# --ci is the form CI runs (ctest "failure_injection", under 2 minutes on 2
# cores): each class once on the cheapest inputs (the beam level of case 05,
# the tiny solid): one full disk (a small tmpfs, skipped where mount is not
# allowed or --no-mount is given) and one file-size limit (ulimit -f: a write
# past 8 KiB fails with EFBIG), one memory limit (ulimit -v 400 MB), each signal once (INT at the
# start, TERM and QUIT while solving, HUP while writing, PIPE from a reader
# that goes away), two runs into one folder at once, and `mpirun -n 2` on
# two commands (one that runs across ranks, one that refuses them).
#
# --quick is the longer bounded form (about 15 minutes): the tiny case, every
# signal at every moment, full disk, two runs at once, mpirun on every
# command; memory limits with short time limits. The full form adds the
# memory trials on case 08 at 400 MB and 600 MB (the hang of issue 33, 9),
# the harmonic level on a full disk and larger time limits.
set -uo pipefail

here="$(cd "$(dirname "$0")/.." && pwd)"
quick=0
ci=0
no_mount=0
keep=0
binary="$here/build/coremodal"
for arg in "$@"; do
    case "$arg" in
        --quick) quick=1 ;;
        --ci) ci=1; quick=1 ;;
        --no-mount) no_mount=1 ;;
        --keep) keep=1 ;;
        -h|--help) sed -n '2,40p' "$0"; exit 0 ;;
        *) binary="$(realpath "$arg")" ;;
    esac
done
[[ -x "$binary" ]] || { echo "failure_injection: no coremodal at $binary (build it, or give its path)" >&2; exit 2; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cases="$here/cases"
work="$(mktemp -d /tmp/coremodal-failure-injection.XXXXXX)"
mounts=()
cleanup() {
    for m in "${mounts[@]}"; do umount "$m" 2>/dev/null; done
    [[ $keep == 1 ]] && echo "trial folders kept in $work" || rm -rf "$work"
}
trap cleanup EXIT

tried=0; n_ok=0; n_clear=0; n_crash=0; n_hang=0; n_lost=0
start_time=$(date +%s)

# ---- the inputs ----------------------------------------------------------

# A steel tube of 0.5 m, about 1 s at the solid level (tests/support/tiny_case.hpp).
tiny_case() {
    cat <<'EOF'
name = "tiny"

[core]
inner_diameter = "76 mm"
wall = "15 mm"
length = "0.5 m"
material = { E = "210 GPa", nu = 0.3, density = "7850 kg/m^3" }

[analysis]
modes = 12

[mesh]
around = 8
along = 4
through_wall = 1
EOF
}
# The same with 2 x 16 x 40 hex20: a solve of a few seconds to be interrupted in.
slow_case() { tiny_case | sed -e 's/^around = 8/around = 16/' -e 's/^along = 4/along = 40/' -e 's/^through_wall = 1/through_wall = 2/'; }
sweep_table() {
    cat <<EOF

[$1]
modes = 6
parameters = [{ key = "core.length", values = ["0.5 m", "0.6 m"] }]
EOF
}
# A clamped rest roll with a [calibration] of 9 points (tests/app/test_study_cli.cpp).
stand_case() {
    cat <<'EOF'
name = "stand"

[core]
inner_diameter = "76 mm"
wall = "15 mm"
length = "2 m"

[rest_paper]
thickness = "10 mm"

[supports]
type = "clamped"

[supports.left]
length = "70 mm"

[mesh]
through_wall = 1
through_rest_paper = 1
around = 8
along = 16

[calibration]
modes = 4
holdout_every = 3
parameters = [
  { key = "core.length", values = ["1.2 m", "1.7 m", "2.2 m"] },
  { key = "rest_paper.thickness", values = ["5 mm", "15 mm", "30 mm"] },
]
EOF
}
iso_case() {
    cat <<'EOF'
name = "iso"
model = "beam"
[core]
inner_diameter = "76 mm"
wall = "15 mm"
length = "1.5 m"
material = "paperboard_core"
[analysis]
modes = 14
EOF
}
measurements() {
    cat <<'EOF'
parameters = ["core.material.E_z", "core.material.G_thetaz"]
[[measurement]]
case = "iso.toml"
mode = "bending n=1 m=2"
frequency = "133.2 Hz"
uncertainty = "0.3 Hz"
[[measurement]]
case = "iso.toml"
mode = "bending n=1 m=3"
frequency = "340 Hz"
EOF
}

# A python stand-in that never finishes a picture: coremodal is then sure
# to be in its writing step. It notes its pid in $1/python.pid.
sleeping_python() {
    cat >"$1/slow-python" <<EOF
#!/bin/sh
echo \$\$ > "$1/python.pid"
exec sleep 300
EOF
    chmod +x "$1/slow-python"
}

# A trial folder with the inputs, a sentinel and (optionally) an earlier result.
new_trial_dir() {
    local d="$work/t$tried"
    mkdir -p "$d"
    tiny_case >"$d/tiny.toml"
    slow_case >"$d/slow.toml"
    { tiny_case; sweep_table study; } >"$d/study.toml"
    stand_case >"$d/cal.toml"
    iso_case >"$d/iso.toml"
    measurements >"$d/m.toml"
    echo "the user's notes, $(date)" >"$d/notes.txt"
    sleeping_python "$d"
    echo "$d"
}

# A digest of a folder's files (names and contents), "" if it does not exist.
digest() { [[ -d "$1" ]] && (cd "$1" && find . -type f -print0 | sort -z | xargs -0 -r sha1sum | sha1sum | cut -c1-16); }

# ---- one trial -------------------------------------------------------------

# judge NAME DIR RC EXPECT_SIGNAL OUT [EARLIER_DIGEST]: classifies and prints a row.
judge() {
    local name="$1" d="$2" rc="$3" sig="$4" out="$5" earlier="${6:-}"
    local err="$d/stderr.txt" verdict note=""
    local sentinel_ok=1 earlier_ok=1
    [[ -f "$d/notes.txt" ]] && grep -q "the user's notes" "$d/notes.txt" || sentinel_ok=0
    if [[ -n "$earlier" ]]; then
        local now_out now_prev
        now_out="$(digest "$d/$out")"; now_prev="$(digest "$d/$out.previous")"
        [[ "$now_out" == "$earlier" || "$now_prev" == "$earlier" ]] || earlier_ok=0
    fi
    local partial
    partial="$(find "$d" -maxdepth 2 -name '*.partial-*' 2>/dev/null | head -1)"
    local orphan=""
    if [[ -f "$d/python.pid" ]] && kill -0 "$(cat "$d/python.pid")" 2>/dev/null; then
        orphan="python $(cat "$d/python.pid")"
        kill "$(cat "$d/python.pid")" 2>/dev/null
    fi
    local dump=0
    grep -qE "Caught signal|terminate called|Segmentation|Aborted|core dumped|PETSC ERROR|HDF5-DIAG|stack trace" "$err" 2>/dev/null && dump=1
    if [[ $sentinel_ok == 0 || $earlier_ok == 0 ]]; then
        verdict=lost; note="sentinel $([[ $sentinel_ok == 1 ]] && echo kept || echo CHANGED), earlier result $([[ $earlier_ok == 1 ]] && echo kept || echo CHANGED)"
    elif [[ $rc == hang ]]; then
        verdict=hang
    elif [[ $dump == 1 || $rc == 59 || $rc == 134 || $rc == 139 || $rc == 136 || $rc == 135 || -n "$partial" || -n "$orphan" ]]; then
        verdict=crash
        [[ -n "$partial" ]] && note="left ${partial#$d/}"
        [[ -n "$orphan" ]] && note="$note orphaned $orphan"
        [[ $dump == 1 ]] && note="$note $(grep -m1 -oE "Caught signal[^.]*|terminate called[^\n]*|Segmentation[^\n]*|PETSC ERROR[^\n]{0,60}|HDF5-DIAG[^\n]{0,40}|core dumped" "$err" | head -1)"
    elif [[ $rc == 0 ]]; then
        verdict=ok
    elif [[ $sig != 0 && $rc == $((128 + sig)) ]]; then
        verdict=clear; note="exit $rc"
    elif [[ $rc -ge 128 ]]; then
        verdict=crash; note="killed by signal $((rc - 128))"
    elif grep -qE "coremodal: |FAILED" "$err" "$d/stdout.txt" 2>/dev/null; then
        verdict=clear; note="$(cat "$err" "$d/stdout.txt" 2>/dev/null | grep -m1 -E "coremodal: |FAILED" | cut -c1-90)"
    else
        verdict=crash; note="exit $rc without a coremodal message: $(head -c 80 "$err" | tr '\n' ' ')"
    fi
    case $verdict in
        ok) n_ok=$((n_ok + 1)) ;; clear) n_clear=$((n_clear + 1)) ;; crash) n_crash=$((n_crash + 1)) ;;
        hang) n_hang=$((n_hang + 1)) ;; lost) n_lost=$((n_lost + 1)) ;;
    esac
    printf '%-44s %-6s rc=%-5s %s\n' "$name" "$verdict" "$rc" "$note"
}

# run_trial NAME TIMEOUT OUT EARLIER(0|1) [PREFIX...] -- ARGS...: runs coremodal in a
# fresh trial folder (after an earlier result into OUT when asked) and judges it.
run_trial() {
    local name="$1" limit="$2" out="$3" earlier_wanted="$4"
    shift 4
    local prefix=()
    while [[ $# -gt 0 && "$1" != "--" ]]; do prefix+=("$1"); shift; done
    shift
    tried=$((tried + 1))
    local d
    d="$(new_trial_dir)"
    local earlier=""
    if [[ $earlier_wanted == 1 ]]; then
        (cd "$d" && COREMODAL_PYTHON=/nonexistent timeout 120 "$binary" "$@" -o "$out" >/dev/null 2>&1)
        earlier="$(digest "$d/$out")"
        [[ -z "$earlier" ]] && echo "  (no earlier result for $name: the serial run failed)"
    fi
    local rc output=(-o "$out")
    [[ $out == - ]] && output=()
    { (cd "$d" && timeout -k 5 "$limit" "${prefix[@]}" "$binary" "$@" "${output[@]}" >"$d/stdout.txt" 2>"$d/stderr.txt" </dev/null); } 2>/dev/null
    rc=$?
    [[ $rc == 124 || $rc == 137 ]] && rc=hang
    judge "$name" "$d" "$rc" 0 "$out" "$earlier"
}

# ---- signals -----------------------------------------------------------------

signal_number() { kill -l "$1"; }

# signal_trial SIG MOMENT: `run` of the slow case; the signal at the start
# (0.2 s in), while solving (stdout says so) or while writing (python runs).
signal_trial() {
    local sig="$1" moment="$2" case_file=slow.toml
    tried=$((tried + 1))
    local d
    d="$(new_trial_dir)"
    [[ $moment == write ]] && case_file=tiny.toml
    (cd "$d" && COREMODAL_PYTHON=/nonexistent "$binary" run tiny.toml -o out -q >/dev/null 2>&1)
    local earlier
    earlier="$(digest "$d/out")"
    (cd "$d" && exec env COREMODAL_PYTHON="$d/slow-python" "$binary" run "$case_file" -o out >"$d/stdout.txt" 2>"$d/stderr.txt" </dev/null) &
    local pid=$!
    local ready=0
    for _ in $(seq 1 600); do
        case $moment in
            start) sleep 0.2; ready=1 ;;
            solve) grep -q "solving" "$d/stdout.txt" 2>/dev/null && ready=1 ;;
            write) [[ -f "$d/python.pid" ]] && ready=1 ;;
        esac
        [[ $ready == 1 ]] && break
        kill -0 $pid 2>/dev/null || break
        sleep 0.1
    done
    kill -s "$sig" $pid 2>/dev/null
    local rc="" waited=0
    while kill -0 $pid 2>/dev/null && [[ $waited -lt 400 ]]; do sleep 0.1; waited=$((waited + 1)); done
    if kill -0 $pid 2>/dev/null; then
        kill -9 $pid 2>/dev/null; { wait $pid; } 2>/dev/null; rc=hang
    else
        { wait $pid; } 2>/dev/null; rc=$?
    fi
    local note_moment="$moment"
    [[ $ready == 0 ]] && note_moment="$moment (ended before it)"
    judge "signal $sig at $note_moment" "$d" "$rc" "$(signal_number "$sig")" out "$earlier"
}

# A reader that goes away: `run ... | head -2` (SIGPIPE on the next line).
pipe_trial() {
    tried=$((tried + 1))
    local d
    d="$(new_trial_dir)"
    (cd "$d" && COREMODAL_PYTHON=/nonexistent "$binary" run tiny.toml -o out -q >/dev/null 2>&1)
    local earlier
    earlier="$(digest "$d/out")"
    (cd "$d" && timeout -k 5 120 "$binary" run slow.toml -o out --no-plots 2>"$d/stderr.txt" | head -2 >/dev/null)
    local rc=${PIPESTATUS[0]}
    [[ $rc == 124 || $rc == 137 ]] && rc=hang
    judge "run | head -2 (SIGPIPE)" "$d" "$rc" 13 out "$earlier"
}

# ---- two runs at once ------------------------------------------------------

two_runs_trial() {
    tried=$((tried + 1))
    local d
    d="$(new_trial_dir)"
    (cd "$d" && COREMODAL_PYTHON=/nonexistent "$binary" run tiny.toml -o out -q >/dev/null 2>&1)
    local earlier
    earlier="$(digest "$d/out")"
    (cd "$d" && exec env COREMODAL_PYTHON="$d/slow-python" "$binary" run tiny.toml -o out -q >/dev/null 2>&1) &
    local first=$!
    for _ in $(seq 1 600); do [[ -f "$d/python.pid" ]] && break; sleep 0.1; done
    local rc
    (cd "$d" && timeout 60 "$binary" run tiny.toml -o out -q --no-plots >"$d/stdout.txt" 2>"$d/stderr.txt")
    rc=$?
    [[ $rc == 124 ]] && rc=hang
    # The first run may finish now; its result replaces the earlier one (kept as .previous).
    kill "$(cat "$d/python.pid")" 2>/dev/null
    wait $first
    local first_rc=$?
    rm -f "$d/python.pid"
    judge "two runs into one --output (second)" "$d" "$rc" 0 out "$earlier"
    echo "  (the first run: exit $first_rc, its result $([[ -f "$d/out/summary.json" ]] && echo in place || echo MISSING))"
}

# ---- a full disk -----------------------------------------------------------

# mount_small DIR SIZE: a tmpfs of SIZE at DIR; fails (with the reason on stdout) where not allowed.
mount_small() {
    mkdir -p "$1"
    if [[ $no_mount == 1 ]]; then
        echo "skipped: --no-mount"
        return 1
    fi
    if ! mount -t tmpfs -o "size=$2" tmpfs "$1" 2>"$work/mount.err"; then
        echo "skipped: mount -t tmpfs not allowed here ($(head -c 100 "$work/mount.err"))"
        return 1
    fi
    mounts+=("$1")
}

# disk_trial NAME SIZE FILL_KB ARGS...: ARGS run with --output on a tmpfs of
# SIZE filled but FILL_KB; an earlier result written there first (before the fill).
disk_trial() {
    local name="$1" size="$2" fill_kb="$3"
    shift 3
    tried=$((tried + 1))
    local d
    d="$(new_trial_dir)"
    if ! mount_small "$d/disk" "$size" >"$d/skip.txt"; then
        tried=$((tried - 1))
        printf '%-44s %s\n' "$name" "$(cat "$d/skip.txt")"
        return
    fi
    echo "the user's notes, on the small disk" >"$d/disk/notes-on-disk.txt"
    (cd "$d" && COREMODAL_PYTHON=/nonexistent timeout 120 "$binary" "$@" -o disk/out >/dev/null 2>&1)
    local earlier
    earlier="$(digest "$d/disk/out")"
    # Fill all but FILL_KB.
    local free_kb
    free_kb=$(df -k --output=avail "$d/disk" | tail -1)
    if ((free_kb > fill_kb)); then dd if=/dev/zero of="$d/disk/filler" bs=1k count=$((free_kb - fill_kb)) 2>/dev/null; fi
    local rc
    (cd "$d" && COREMODAL_PYTHON=/nonexistent timeout -k 5 120 "$binary" "$@" -o disk/out >"$d/stdout.txt" 2>"$d/stderr.txt")
    rc=$?
    [[ $rc == 124 || $rc == 137 ]] && rc=hang
    [[ -f "$d/disk/notes-on-disk.txt" ]] || { echo "  the sentinel on the small disk is gone"; rm -f "$d/notes.txt"; }
    judge "$name" "$d" "$rc" 0 disk/out "$earlier"
    # A later run into that folder, with room again, must work.
    rm -f "$d/disk/filler"
    tried=$((tried + 1))
    (cd "$d" && COREMODAL_PYTHON=/nonexistent timeout -k 5 120 "$binary" "$@" -o disk/out >"$d/stdout.txt" 2>"$d/stderr.txt")
    rc=$?
    [[ $rc == 124 || $rc == 137 ]] && rc=hang
    judge "  then the same with room again" "$d" "$rc" 0 disk/out ""
    umount "$d/disk" 2>/dev/null
}

# fsize_trial NAME KB ARGS...: the full disk where no tmpfs can be mounted:
# ARGS run with --output under `ulimit -f KB` (a write past KB KiB fails as
# on a full disk, EFBIG), after an earlier result written without it.
fsize_trial() {
    local name="$1" kb="$2"
    shift 2
    tried=$((tried + 1))
    local d
    d="$(new_trial_dir)"
    (cd "$d" && COREMODAL_PYTHON=/nonexistent timeout 120 "$binary" "$@" -o out >/dev/null 2>&1)
    local earlier rc
    earlier="$(digest "$d/out")"
    (cd "$d" && COREMODAL_PYTHON=/nonexistent timeout -k 5 120 bash -c "ulimit -f $kb; exec \"\$0\" \"\$@\"" \
        "$binary" "$@" -o out >"$d/stdout.txt" 2>"$d/stderr.txt")
    rc=$?
    [[ $rc == 124 || $rc == 137 ]] && rc=hang
    judge "$name" "$d" "$rc" 0 out "$earlier"
}

# A full disk: a tmpfs where mount is allowed; and a file-size limit (a
# second way a write fails, which killed the run by SIGXFSZ before issue 33).
full_disk_trial() {
    local name="$1" size="$2" fill_kb="$3"
    shift 3
    local mark="$work/can-mount"
    if [[ $no_mount == 0 ]] && mkdir -p "$mark" && mount -t tmpfs -o size=64k tmpfs "$mark" 2>/dev/null; then
        umount "$mark"
        disk_trial "$name" "$size" "$fill_kb" "$@"
    else
        printf '%-44s %s\n' "$name" "skipped: no tmpfs can be mounted here (or --no-mount)"
    fi
    fsize_trial "${name/full disk/ulimit -f 8 KiB}" 8 "$@"
}

ci_trials() {
    local case05="$cases/05-beam-level-rest-roll-150x15.8-4320.toml"
    echo "# full disk (a small tmpfs, or ulimit -f)"
    full_disk_trial "full disk: run (beam level, case 05)" 1m 8 run "$case05" --no-plots
    echo "# memory limit (ulimit -v, KiB)"
    # 400 MB: the program loads (at 200 MB its shared libraries do not) and its solve does not fit.
    run_trial "ulimit -v 400000: run tiny" 30 out 1 bash -c 'ulimit -v 400000; exec "$0" "$@"' -- run tiny.toml --no-plots
    echo "# signals, each once"
    signal_trial INT start
    signal_trial TERM solve
    signal_trial QUIT solve
    signal_trial HUP write
    pipe_trial
    echo "# two runs at once"
    two_runs_trial
    echo "# mpirun -n 2"
    local mpi=(mpirun -n 2 --oversubscribe)
    run_trial "mpirun: run (beam, case 05)" 60 out 1 "${mpi[@]}" -- run "$case05" --no-plots
    run_trial "mpirun: campbell (beam)" 60 out 1 "${mpi[@]}" -- campbell "$cases/12-rotation-tester-76x15.toml" --model beam --no-plots
}

# ---- the trials --------------------------------------------------------------

printf '%-44s %-6s %-8s %s\n' "trial" "result" "exit" "note"
printf '%s\n' "--------------------------------------------------------------------------------"

if [[ $ci == 1 ]]; then
    ci_trials
else
echo "# full disk (tmpfs)"
disk_trial "full disk: run (solid, tiny)" 2m 40 run tiny.toml --no-plots
disk_trial "full disk: run (beam level, case 05)" 1m 8 run "$cases/05-beam-level-rest-roll-150x15.8-4320.toml" --no-plots
disk_trial "full disk: batch" 2m 30 batch tiny.toml
disk_trial "full disk: harmonic response (case 13)" 2m 16 response "$cases/13-rest-roll-response-150x15.8-4320.toml" --model harmonic --no-plots
if [[ $quick == 0 ]]; then
    disk_trial "full disk: run (harmonic, case 03 coarse)" 4m 60 run "$cases/03-rest-roll-150x15.8-4320.toml" --model harmonic --mesh coarse --no-plots
    disk_trial "full disk: study (beam)" 2m 30 study study.toml --model beam --no-plots
fi

echo "# memory limits (ulimit -v, KiB)"
if [[ $quick == 1 ]]; then
    run_trial "ulimit -v 400000: run tiny" 20 out 1 bash -c 'ulimit -v 400000; exec "$0" "$@"' -- run tiny.toml --no-plots
    run_trial "ulimit -v 200000: run tiny" 20 out 1 bash -c 'ulimit -v 200000; exec "$0" "$@"' -- run tiny.toml --no-plots
else
    for kb in 200000 400000 600000 2000000; do
        run_trial "ulimit -v $kb: run case 08 coarse" 300 out 1 bash -c "ulimit -v $kb; exec \"\$0\" \"\$@\"" -- \
            run "$cases/08-news-chucks-76x15-2200.toml" --mesh coarse --no-plots
    done
    run_trial "ulimit -v 2000000: run case 03" 600 out 1 bash -c 'ulimit -v 2000000; exec "$0" "$@"' -- \
        run "$cases/03-rest-roll-150x15.8-4320.toml" --no-plots
fi

echo "# signals"
for sig in INT TERM HUP QUIT PIPE; do
    for moment in start solve write; do signal_trial "$sig" "$moment"; done
done
pipe_trial

echo "# two runs at once"
two_runs_trial

echo "# mpirun -n 2 on every command (an earlier result in --output where it writes one)"
mpi=(mpirun -n 2 --oversubscribe)
run_trial "mpirun: run (solid)" 120 out 1 "${mpi[@]}" -- run tiny.toml --no-plots
run_trial "mpirun: run (beam, case 05)" 120 out 1 "${mpi[@]}" -- run "$cases/05-beam-level-rest-roll-150x15.8-4320.toml" --no-plots
run_trial "mpirun: check" 60 - 0 "${mpi[@]}" -- check tiny.toml
run_trial "mpirun: beam" 60 - 0 "${mpi[@]}" -- beam "$cases/05-beam-level-rest-roll-150x15.8-4320.toml"
run_trial "mpirun: batch" 120 out 1 "${mpi[@]}" -- batch tiny.toml
run_trial "mpirun: converge (beam)" 300 out 1 "${mpi[@]}" -- converge tiny.toml --models beam --no-plots -q
run_trial "mpirun: winder" 120 out 1 "${mpi[@]}" -- winder "$cases/11-two-drum-winder.toml" --no-plots
run_trial "mpirun: study (beam)" 120 out 1 "${mpi[@]}" -- study study.toml --model beam --no-plots
run_trial "mpirun: calibrate" 300 out 1 "${mpi[@]}" -- calibrate cal.toml --no-plots -q
run_trial "mpirun: schema" 60 out.json 0 "${mpi[@]}" -- schema
run_trial "mpirun: sensitivity (beam)" 120 out 1 "${mpi[@]}" -- sensitivity iso.toml
run_trial "mpirun: fit" 120 out 1 "${mpi[@]}" -- fit m.toml -q
run_trial "mpirun: campbell (beam)" 120 out 1 "${mpi[@]}" -- campbell "$cases/12-rotation-tester-76x15.toml" --model beam --no-plots
run_trial "mpirun: response (beam)" 120 out 1 "${mpi[@]}" -- response "$cases/13-rest-roll-response-150x15.8-4320.toml" --model beam --no-plots
run_trial "mpirun: response (harmonic)" 300 out 1 "${mpi[@]}" -- response "$cases/13-rest-roll-response-150x15.8-4320.toml" --model harmonic --no-plots
fi

printf '%s\n' "--------------------------------------------------------------------------------"
printf 'tried %d: ok %d, clear error %d, crash %d, hang %d, data lost %d (%d s)\n' \
    "$tried" "$n_ok" "$n_clear" "$n_crash" "$n_hang" "$n_lost" "$(( $(date +%s) - start_time ))"
(( n_crash + n_hang + n_lost == 0 ))
