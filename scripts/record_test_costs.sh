#!/usr/bin/env bash
# Writes tests/test_costs.cmake from the test times of the last full ctest
# run (build/Testing/Temporary/CTestCostData.txt): a COST for every test
# that took 3 s or more, so that ctest -j starts the longest first on a
# fresh checkout. (ctest's own record does not do it there: a checkout has
# none, and ctest cannot read back names with spaces from it.) Run it after
# a full `bash scripts/test.sh` on a quiet machine, when long tests change.
set -euo pipefail
cd "$(dirname "$0")/.."
names=$(mktemp)
ctest --test-dir build -N | sed -n 's/^ *Test *#[0-9]*: //p' > "$names"
python3 - build/Testing/Temporary/CTestCostData.txt tests/test_costs.cmake "$names" <<'PY'
import sys
defined = set(open(sys.argv[3]).read().splitlines())
entries = []
for line in open(sys.argv[1]):
    line = line.rstrip("\n")
    if line == "---":
        break
    name, runs, cost = line.rsplit(" ", 2)
    if int(runs) > 0 and float(cost) >= 3 and name in defined:
        entries.append((float(cost), name))
with open(sys.argv[2], "w") as out:
    out.write("# Written by scripts/record_test_costs.sh: each test's time (s) in the last full\n"
              "# run, as ctest's COST, so that ctest -j starts the longest first. A name no\n"
              "# longer defined is ignored.\n")
    for cost, name in sorted(entries, reverse=True):
        out.write(f"set_tests_properties([=[{name}]=] PROPERTIES COST {cost:.1f})\n")
PY
rm -f "$names"
echo "tests/test_costs.cmake: $(grep -c set_tests_properties tests/test_costs.cmake) tests of 3 s or more"
