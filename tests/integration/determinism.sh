#!/bin/sh
# RIG-6: lock-step runs are deterministic; two runs of the demo on different
# ports give the same messages, cycle for cycle (wall-clock fields ignored).
# Issue 17: an in-process run gives the same messages as the processes.
. "$(dirname "$0")/lib.sh"

expect_status 0 "$hil" run "$HIL_SOURCE/scenarios/demo.yaml" --out "$WORK/a" --port 7701
expect_status 0 "$hil" run "$HIL_SOURCE/scenarios/demo.yaml" --out "$WORK/b" --port 7702
expect_status 0 "$hil" compare "$WORK/a/run.lcmlog" "$WORK/b/run.lcmlog"
expect_output "identical"
expect_status 0 "$hil" run "$HIL_SOURCE/scenarios/demo.yaml" --out "$WORK/c" --in-process
expect_output "in-process"
expect_status 0 "$hil" compare "$WORK/a/run.lcmlog" "$WORK/c/run.lcmlog"
expect_output "identical"
