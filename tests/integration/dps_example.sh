#!/bin/sh
# DPS-1, DPS-2: the example program of TF5200_distance_from_program_start.txt
# runs through the rig and gives exactly the distances the text lists.
. "$(dirname "$0")/lib.sh"

expect_status 0 "$hil" run "$HIL_SOURCE/scenarios/dps/distance_prog_start_example.yaml" --out "$WORK/run" --port 7667
expect_output "PASSED"
expect_output "expectations (plc_sim): 11 passed, 0 failed"
expect_output "limit violations: 0"
