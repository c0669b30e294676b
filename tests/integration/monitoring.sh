#!/bin/sh
# RIG-3, RIG-4: each drive monitor (acceleration P-AXIS-00441/00442, velocity
# P-AXIS-00439/00440, following error P-AXIS-00168, software limit switch
# P-AXIS-00178) trips live in its scenario, the error stops the CNC channel,
# and the offline check names the violation the scenario expects.
. "$(dirname "$0")/lib.sh"

port=7730
for name in acceleration_overload velocity_overload following_error software_limit; do
  expect_status 0 "$hil" run "$HIL_SOURCE/scenarios/monitoring/$name.yaml" --out "$WORK/$name" --port $port
  expect_output "PASSED"
  expect_output "channel stopped: drive error on axis X"
  expect_output "PASS at channel_state=ERROR"
  port=$((port + 1))
done
# Checked on its own, the log still fails: the violation is there.
expect_status 1 "$hil" check "$WORK/acceleration_overload/run.lcmlog"
expect_output "CHECK FAILED"
expect_output "actual acceleration (P-AXIS-00442 limit)"
# The plots: written by hil run, and by hil check --plots.
for png in axis_X.png path.png; do
  [ -s "$WORK/acceleration_overload/plots/$png" ] || fail "hil run drew no plots/$png"
done
expect_status 1 "$hil" check "$WORK/acceleration_overload/run.lcmlog" --plots "$WORK/check_plots"
expect_output "plots: $WORK/check_plots/ (axis_X.png, path.png)"  # X only: no XY contour
[ -s "$WORK/check_plots/axis_X.png" ] || fail "hil check --plots drew no axis_X.png"
