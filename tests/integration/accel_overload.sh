#!/bin/sh
# RIG-3, RIG-4: an acceleration overload is seen live (P-AXIS-00441/00442
# events from the drive simulator) and offline (the checker's violation),
# and both make the run fail.
. "$(dirname "$0")/lib.sh"

expect_status 1 "$hil" run "$HIL_SOURCE/tests/integration/scenarios/accel_overload.yaml" --out "$WORK/run" --port 7730
expect_output "FAILED"
expect_output "P-AXIS-00441"
expect_output "P-AXIS-00442"
expect_status 1 "$hil" check "$WORK/run/run.lcmlog"
expect_output "CHECK FAILED"
expect_output "P-AXIS-00442"
