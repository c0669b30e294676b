#!/bin/sh
# KRN-1, KRN-2: a bad NC line stops the channel after the last good block;
# the scenario's own expectations check position, block and the error event.
. "$(dirname "$0")/lib.sh"

expect_status 0 "$hil" run "$HIL_SOURCE/tests/integration/scenarios/nc_error.yaml" --out "$WORK/run" --port 7720
expect_output "PASSED"
expect_output "line 5 N30"
expect_output "'W5'"
