#!/bin/sh
# RIG-6: in lock-step nothing depends on timing but a participant that is
# really gone. A busy loop on every core beside the run, axis_sim Y under
# SCHED_IDLE (it runs only when nothing else wants its CPU, CPU 0 with the
# other lock-step nodes), and the CNC's answer timeout cut to 2 ms: Y's
# answers often take longer, but its process is alive and running, so the
# CNC waits on (and says so) instead of losing it; the run PASSES, and
# `hil rerun` finds its trace the one a quiet host gives. (A participant that died or was stopped is
# still lost at the timeout: faults.sh, tests/unit/process_state_test.cpp.)
. "$(dirname "$0")/lib.sh"

bin="$WORK/bin"
mkdir -p "$bin"
for exe in hil cnc plc_sim hil_logger; do ln -s "$HIL_BIN/$exe" "$bin/$exe"; done
printf '#!/bin/sh\ncase "$*" in *"--axis Y"*) exec chrt --idle 0 "%s/axis_sim" "$@";; esac\nexec "%s/axis_sim" "$@"\n' \
  "$HIL_BIN" "$HIL_BIN" >"$bin/axis_sim"
chmod +x "$bin/axis_sim"

loads=""
for cpu in $(seq 0 $(($(nproc) - 1))); do
  taskset -c "$cpu" sh -c 'while :; do :; done' &
  loads="$loads $!"
done
trap 'kill $loads 2>/dev/null' EXIT

scenario="$HIL_SOURCE/tests/integration/scenarios/short_move.yaml"
expect_status 0 "$bin/hil" run "$scenario" --out "$WORK/loaded" --port 7793 --bin-dir "$bin" --answer-timeout-ms 2 \
  --cpu 0
expect_output "PASSED"
waits=$(grep -c "its process alive and running: waiting on" "$WORK/loaded/cnc.out" || true)
echo "loaded host: the cnc waited on a slow, running participant $waits time(s)"
[ "$waits" -gt 0 ] || fail "the load did not make any answer late: nothing was tested"
! grep -q " lost" "$WORK/loaded/cnc.out" || fail "a participant that was only slow was lost"
kill $loads 2>/dev/null
trap - EXIT
# The same trace as without the load: this build reruns it message for message.
expect_status 0 "$hil" rerun "$WORK/loaded/run.lcmlog"
expect_output "identical: 208 cycles"
