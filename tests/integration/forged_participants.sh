#!/bin/sh
# RIG-12, RIG-9: anyone on the bus may read the run id, but only the run's
# own processes hold its secret (run.key in the run folder, mode 0600).
# At cycle 1000 of the demo hil_inject, without the secret, sends the cnc's
# RUN_END, a plc_sim PASS verdict, an AXIS_Y_STATE and an HLI_CONTROL (feed
# hold) of this run, and 40 'logger' heartbeats: every node refuses and
# counts them (unauthenticated), the run goes on and PASSES. Then the logger
# is SIGKILLed while the same forged heartbeats go on for 3 s: the CNC is
# not fooled, it loses the logger within its 2 s and the run FAILS.
. "$(dirname "$0")/lib.sh"
port=7792
url="udpm://239.255.76.67:$port?ttl=0"

"$HIL_BIN/hil_inject" --url "$url" --at-cycle 1000 --forge-run-end --forge-pass --forge-state Y --forge-control \
  --forge-alive 40 >"$WORK/inject.out" 2>&1 &
injector=$!
expect_status 0 "$hil" run "$HIL_SOURCE/scenarios/demo.yaml" --out "$WORK/forged" --port $port
wait "$injector" || { cat "$WORK/inject.out"; fail "hil_inject did not act"; }
expect_output "PASSED"
# Each node counts what reached it before it ended (the heartbeats go on 2 s).
refused="AXIS_Y_STATE: 1 unauthenticated; HIL_PARTICIPANT: [0-9]* unauthenticated; HLI_CONTROL: 1 unauthenticated"
grep -q "^  cnc: $refused" "$WORK/last.out" || fail "the cnc did not refuse the forged messages"
grep -q "^  logger: AXIS_Y_STATE: 1 unauthenticated; HIL_EVENT: 1 unauthenticated; HIL_PARTICIPANT: [0-9]* unauthenticated" \
  "$WORK/last.out" || fail "the logger did not refuse the forged messages"
grep -q "^  plc_sim: HIL_EVENT: 1 unauthenticated; HIL_PARTICIPANT: [0-9]* unauthenticated" "$WORK/last.out" ||
  fail "plc_sim did not refuse the forged RUN_END"
# Not recorded: plc_sim's own verdicts are all the log holds.
expect_output "expectations (plc_sim): 3 passed, 0 failed of 3 verdict(s): the scenario's 3"
expect_status 0 "$hil" check "$WORK/forged/run.lcmlog"

# The logger killed, its heartbeats forged: lost all the same.
bin="$WORK/bin"
mkdir -p "$bin"
for exe in hil cnc plc_sim axis_sim; do ln -s "$HIL_BIN/$exe" "$bin/$exe"; done
printf '#!/bin/sh\necho $$ >"%s/logger.pid"\nexec "%s/hil_logger" "$@"\n' "$WORK" "$HIL_BIN" >"$bin/hil_logger"
chmod +x "$bin/hil_logger"
"$HIL_BIN/hil_inject" --url "$url" --at-cycle 1000 --kill-pid-file "$WORK/logger.pid" --forge-alive 60 \
  >"$WORK/inject.out" 2>&1 &
injector=$!
expect_status 1 "$bin/hil" run "$HIL_SOURCE/scenarios/demo.yaml" --out "$WORK/killed" --port $port --bin-dir "$bin"
wait "$injector" || { cat "$WORK/inject.out"; fail "hil_inject did not act"; }
expect_output "FAILED"
grep -q "logger lost: no heartbeat for" "$WORK/killed/cnc.out" || fail "the cnc was fooled by forged heartbeats"
