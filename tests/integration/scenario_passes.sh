#!/bin/sh
# RIG-5: one scenario through the whole rig passes (its expectations, the
# offline check, every node). In-process (issue 17): these tests are about
# the CNC's functions, not the processes; the same nodes, messages and log
# (integration.determinism compares them with a run of separate processes).
# Usage: scenario_passes.sh SCENARIO.yaml
. "$(dirname "$0")/lib.sh"

expect_status 0 "$hil" run "$1" --out "$WORK/run" --in-process
expect_output "PASSED"
