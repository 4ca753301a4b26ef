#!/bin/bash
# bench/levels_result_set.sh BINARY OUTDIR: the before/after set of issue 34 (cases 01 02 05 07 08 12 13 15 16 at
# the beam/harmonic levels, coarse meshes; run, campbell, response, limits, sensitivity, converge). Compare two
# sets with bench/same_folders.py BEFORE AFTER.
B=$(realpath "$1"); O=$(realpath -m "$2"); mkdir -p "$O"; cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
r() { name=$1; shift; s=$(date +%s.%N); $B "$@" -q --no-plots --force -o $O/$name > $O/$name.log 2>&1; echo "$name rc=$? $(echo "$(date +%s.%N) - $s" | bc)s" >> $O/index.txt; }
r run01h run cases/01-iso-free-free-76x15.toml --model harmonic --mesh coarse
r run01b run cases/01-iso-free-free-76x15.toml --model beam
r run02h run cases/02-clamped-76x15.toml --model harmonic --mesh coarse
r run02b run cases/02-clamped-76x15.toml --model beam
r run05 run cases/05-beam-level-rest-roll-150x15.8-4320.toml
r run07 run cases/07-rotogravure-chucks-150x15.8-4320.toml --mesh coarse
r run08 run cases/08-news-chucks-76x15-2200.toml --mesh coarse
r camp12b campbell cases/12-rotation-tester-76x15.toml
r camp12h campbell cases/12-rotation-tester-76x15.toml --model harmonic --mesh coarse
r resp13b response cases/13-rest-roll-response-150x15.8-4320.toml
r resp13h response cases/13-rest-roll-response-150x15.8-4320.toml --model harmonic --mesh coarse
r run15b run cases/15-rest-roll-on-web-76x15-2211.toml --model beam
r run15c run cases/15-rest-roll-on-web-76x15-2211.toml --mesh coarse
r lim16 limits cases/16-limits-rotogravure-150x15.8-4320.toml
r sens01b sensitivity cases/01-iso-free-free-76x15.toml --model beam
r sens07 sensitivity cases/07-rotogravure-chucks-150x15.8-4320.toml --mesh coarse
r conv05 converge cases/05-beam-level-rest-roll-150x15.8-4320.toml --models beam --levels 3 --repeats 1
