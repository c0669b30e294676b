#!/bin/sh
# DDTG-1 .. DDTG-4: the delete distance to go scenarios through the whole
# rig: the PLC simulator raises the signal over LCM, the CNC reacts, the
# drives follow, the log is checked.
. "$(dirname "$0")/lib.sh"

port=7750
for f in "$HIL_SOURCE"/scenarios/ddtg/*.yaml; do
  name=$(basename "$f" .yaml)
  expect_status 0 "$hil" run "$f" --out "$WORK/$name" --port $port
  expect_output "PASSED"
  port=$((port + 1))
done
