#!/bin/sh
# RIG-5 (issue 19): a never: the run breaks FAILS the run, naming the first
# cycle it broke in and the value seen; its verdict event carries that
# cycle in the log (not the run's last), and the log stays complete.
. "$(dirname "$0")/lib.sh"
scenarios="$HIL_SOURCE/tests/integration/scenarios"

expect_status 1 "$hil" run "$scenarios/never_broken.yaml" --out "$WORK/run" --in-process
expect_output "FAILED"
expect_output "  because 1 expectation(s) failed"
expect_output "FAIL never axis_position_mm.X>=5: broken in cycle "
expect_output "expectations (plc_sim): 1 passed, 1 failed"
expect_output "log complete: yes"
# The cycle named is the one the verdict event is stamped with, and X was
# beyond 5 mm there: the first such cycle of the log's HLI states.
line=$(grep -o "broken in cycle [0-9]*: axis_position_mm.X=[0-9.]*" "$WORK/last.out" | head -1)
cycle=$(echo "$line" | sed 's/broken in cycle \([0-9]*\):.*/\1/')
x=$(echo "$line" | sed 's/.*X=//')
[ -n "$cycle" ] || fail "no cycle named"
awk -v x="$x" 'BEGIN { exit !(x >= 5 && x < 5.1) }' || fail "X=$x is not just beyond 5 mm"
grep -q "cycle $cycle \[plc_sim\] .*FAIL never" "$WORK/run/report.txt" || fail "the verdict event is not stamped with cycle $cycle"
