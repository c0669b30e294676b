#!/bin/sh
# RIG-6, RIG-9: faults end the run safely. hil_inject kills axis_sim Y at
# cycle 1000 of the demo: the CNC's watchdog loses it after 5 s, the channel
# stops as on a drive error (ERROR, on the path), the run goes on without Y
# to its end and the report says who went silent and when. Then it kills
# the logger: the CNC notices the missing heartbeat within 2 s, while the
# run goes on, and stops the channel; the log is incomplete and says so.
. "$(dirname "$0")/lib.sh"

bin="$WORK/bin"
mkdir -p "$bin"
for exe in hil cnc plc_sim; do ln -s "$HIL_BIN/$exe" "$bin/$exe"; done
# Wrappers that leave their pid where hil_inject finds it.
printf '#!/bin/sh\ncase "$*" in *"--axis Y"*) echo $$ >"%s/axis_sim_Y.pid";; esac\nexec "%s/axis_sim" "$@"\n' \
  "$WORK" "$HIL_BIN" >"$bin/axis_sim"
printf '#!/bin/sh\necho $$ >"%s/logger.pid"\nexec "%s/hil_logger" "$@"\n' "$WORK" "$HIL_BIN" >"$bin/hil_logger"
chmod +x "$bin/axis_sim" "$bin/hil_logger"
# run_killing NAME: the demo, with the node whose pid is in $WORK/NAME.pid
# killed at cycle 1000; the run folder is $WORK/NAME. It must FAIL.
run_killing() {
  "$HIL_BIN/hil_inject" --url "udpm://239.255.76.67:7790?ttl=0" --at-cycle 1000 --kill-pid-file "$WORK/$1.pid" \
    >"$WORK/inject.out" 2>&1 &
  injector=$!
  expect_status 1 "$bin/hil" run "$HIL_SOURCE/scenarios/demo.yaml" --out "$WORK/$1" --port 7790 --bin-dir "$bin"
  wait "$injector" || { cat "$WORK/inject.out"; fail "hil_inject did not act"; }
  expect_output "FAILED"
  tail -n 1 "$WORK/$1/cnc.out" | grep -q "channel ERROR" || fail "the channel did not end in ERROR"
}

run_killing axis_sim_Y
expect_output "  because log: axis_sim Y went silent: the cnc lost it at cycle 10"
expect_output "[cnc] error axis Y: axis_sim Y lost: no answer to cycle 10"
expect_output "within 5000 ms; the run goes on without it"
grep -q "axis_sim Y is silent, its process gone" "$WORK/axis_sim_Y/cnc.out" || fail "the cnc did not say the process is gone"
expect_output "channel stopped: drive error on axis Y (axis_sim Y lost: no answer to cycle 10"
expect_output "axis_sim Y 137 ("
# RIG-7: the rerun loses axis Y at the same cycle and stops the same way.
expect_status 0 "$hil" rerun "$WORK/axis_sim_Y/run.lcmlog"
expect_output "identical: "

run_killing logger
expect_output "logger 137 ("
expect_output "because log: the logger did not close the log (no HIL_LOG_END)"
grep -q "logger lost: no heartbeat for [0-9]* ms at cycle" "$WORK/logger/cnc.out" || fail "the cnc did not notice"
grep -q "channel stopped: logger lost" "$WORK/logger/cnc.out" || fail "the channel did not stop"
