#!/bin/sh
# RIG-6, RIG-9, RIG-12: forged and foreign traffic. At cycle 300 hil_inject,
# with the run's secret (a faulty participant of the run), sends an
# AXIS_Y_STATE and an HLI_CONTROL (feed hold on) of this run a million cycles
# ahead and an hli_control_t on AXIS_X_STATE; then another run's
# AXIS_X_STATE with a drive error, an AXIS_Y_STATE of this run with a drive
# error but without the run's MAC (an outsider who read the run id), and
# three 19-byte datagrams whose channel name has no NUL.
# The CNC takes none of them: axis Y's software limit error still stops the
# channel in N20, as the scenario expects. The logger survives the datagrams.
# The run FAILS, for the stated reason: messages of this run it cannot
# account for; another run's message is only counted. `hil check` says so.
. "$(dirname "$0")/lib.sh"
scenarios="$HIL_SOURCE/tests/integration/scenarios"
port=7770

"$HIL_BIN/hil_inject" --url "udpm://239.255.76.67:$port?ttl=0" --at-cycle 300 --forge-state Y --forge-control \
  --foreign-state X --wrong-type X --unsigned-state Y --unframed 3 --key-file "$WORK/run/run.key" \
  >"$WORK/inject.out" 2>&1 &
injector=$!
expect_status 1 "$hil" run "$scenarios/y_software_limit.yaml" --out "$WORK/run" --port $port
wait "$injector" || { cat "$WORK/inject.out"; fail "hil_inject did not act"; }
expect_output "FAILED"
expect_output "expectations (plc_sim): 3 passed, 0 failed"
expect_output "channel stopped: drive error on axis Y (software limit switch P-AXIS-00177/00178)"
expect_output "exit status: cnc 0, logger 0, axis_sim X 0, axis_sim Y 0, plc_sim 0"
# What the CNC refused, per channel. Datagrams LCM could not frame count as
# "(malformed datagram)" where LCM, reading the name on past the datagram,
# found a NUL within 63 characters (how many depends on its buffer).
grep -q "^  cnc: .*AXIS_X_STATE: 1 foreign run, 1 undecodable; AXIS_Y_STATE: 1 wrong cycle, 1 unauthenticated; HLI_CONTROL: 1 wrong cycle" \
  "$WORK/last.out" || fail "the cnc's refusals are not reported per channel"
expect_output "because log: cnc refused messages of this run or unreadable"
expect_output "because log: AXIS_Y_STATE: 1 message(s) of a wrong cycle"
# The logger recorded neither the foreign, the unreadable nor the unsigned message.
grep -q "^  logger: .*AXIS_X_STATE: 1 foreign run, 1 undecodable; AXIS_Y_STATE: 1 unauthenticated" "$WORK/last.out" ||
  fail "logger's refusals"

expect_status 1 "$hil" check "$WORK/run/run.lcmlog"
expect_output "CHECK FAILED"
expect_output "AXIS_Y_STATE: 1 wrong cycle"
expect_output "AXIS_X_STATE: 1 foreign run, 1 undecodable"
