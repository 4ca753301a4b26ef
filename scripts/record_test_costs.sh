#!/usr/bin/env bash
# Writes tests/test_costs.cmake from the test times of a full ctest run's
# console output (LOG: what `bash scripts/test.sh` printed, saved): a COST
# for every test that took 3 s or more, so that ctest -j starts the longest
# first on a fresh checkout. (ctest's own record cannot do it: a checkout
# has none, and ctest 3.25 keeps a name in it only up to its first space.)
# Run it after a full run on a quiet machine, when long tests change:
#
#   bash scripts/test.sh | tee /tmp/suite.log
#   bash scripts/record_test_costs.sh /tmp/suite.log
set -euo pipefail
cd "$(dirname "$0")/.."
log=${1:?"usage: record_test_costs.sh LOG (a full ctest run's output)"}
names=$(mktemp)
ctest --test-dir build -N | sed -n 's/^ *Test *#[0-9]*: //p' > "$names"
python3 - "$log" tests/test_costs.cmake "$names" <<'PY'
import re, sys
defined = set(open(sys.argv[3]).read().splitlines())
entries = []
for line in open(sys.argv[1]):
    m = re.search(r"Test +#\d+: (.*?) \.+\s+Passed\s+([\d.]+) sec", line)
    if m and float(m.group(2)) >= 3 and m.group(1) in defined:
        entries.append((float(m.group(2)), m.group(1)))
if len(entries) < 10:
    sys.exit(f"record_test_costs: only {len(entries)} passed tests of 3 s or more in {sys.argv[1]}: not a full run's output")
with open(sys.argv[2], "w") as out:
    out.write("# Written by scripts/record_test_costs.sh: each test's time (s) in the last full\n"
              "# run, as ctest's COST, so that ctest -j starts the longest first. A name no\n"
              "# longer defined is ignored.\n")
    for cost, name in sorted(entries, reverse=True):
        out.write(f"set_tests_properties([=[{name}]=] PROPERTIES COST {cost:.1f})\n")
print(f"{sys.argv[2]}: {len(entries)} tests of 3 s or more")
PY
rm -f "$names"
