#!/bin/sh
# RIG-5: one scenario through the whole rig passes (its expectations, the
# offline check, every process). Usage: scenario_passes.sh SCENARIO.yaml
. "$(dirname "$0")/lib.sh"

expect_status 0 "$hil" run "$1" --out "$WORK/run" --port 7760
expect_output "PASSED"
