#!/bin/sh
# RIG-6: lock-step runs are deterministic; two runs of the demo on different
# ports give the same messages, cycle for cycle (wall-clock fields ignored).
. "$(dirname "$0")/lib.sh"

expect_status 0 "$hil" run "$HIL_SOURCE/scenarios/demo.yaml" --out "$WORK/a" --port 7701
expect_status 0 "$hil" run "$HIL_SOURCE/scenarios/demo.yaml" --out "$WORK/b" --port 7702
expect_status 0 "$hil" compare "$WORK/a/run.lcmlog" "$WORK/b/run.lcmlog"
expect_output "identical"
