#!/bin/sh
# RIG-8, RIG-6, RIG-7: faults declared in a scenario, as separate processes.
# The killed axis: axis_sim Y's process really dies by SIGKILL at 2.0 s, the
# CNC's watchdog stops the channel, the run passes as the scenario expects.
# Two process runs and an in-process run of the message-loss scenario give
# the same log message for message (seeded faults are deterministic), and
# `hil rerun` reproduces a run with faults. In real time, axis X answering
# 3 ms late from 1 s to 4 s is counted late and the motion goes on.
. "$(dirname "$0")/lib.sh"
faults="$HIL_SOURCE/scenarios/faults"

expect_status 0 "$hil" run "$faults/killed_axis_lockstep.yaml" --out "$WORK/killed" --port 7801
expect_output "PASSED"
expect_output "axis_sim Y 137"
grep -q "axis_sim Y lost: watchdog: no answer for 21 cycles (watchdog_cycles 20)" "$WORK/killed/cnc.out" ||
  fail "the cnc did not lose axis_sim Y by its watchdog"
expect_status 0 "$hil" rerun "$WORK/killed/run.lcmlog"
expect_output "identical"

for run in a b; do
  expect_status 0 "$hil" run "$faults/hli_control_loss_m_handshake.yaml" --out "$WORK/loss_$run" --port 7802
done
expect_status 0 "$hil" run "$faults/hli_control_loss_m_handshake.yaml" --out "$WORK/loss_in" --in-process
for other in b in; do
  expect_status 0 "$hil" compare "$WORK/loss_a/run.lcmlog" "$WORK/loss_$other/run.lcmlog"
  expect_output "identical"
done
expect_status 0 "$hil" rerun "$WORK/loss_a/run.lcmlog"
expect_output "identical"

# Real time: thousands of late answers from axis X, none lost, the run passes.
expect_status 0 "$hil" run "$faults/late_drive_realtime.yaml" --out "$WORK/late" --port 7803
expect_output "PASSED"
late=$(awk '$1 == "axis_sim" && $2 == "X" {print $4}' "$WORK/last.out")
[ "${late:-0}" -ge 2000 ] || fail "axis X's late answers are not counted (got '${late}')"
