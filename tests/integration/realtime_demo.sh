#!/bin/sh
# RIG-6, RIG-9: the demo's program in real-time mode through every process
# over LCM: it passes on expectations that do not depend on timing, and the
# report shows the tick's jitter, the overruns, each participant's answers
# and how each node was scheduled. The figures themselves depend on the
# machine's load (a quiet machine: bench/realtime_run.sh, PERFORMANCE.md).
. "$(dirname "$0")/lib.sh"

expect_status 0 "$hil" run "$HIL_SOURCE/scenarios/rig/realtime_demo.yaml" --out "$WORK/run" --port 7771
expect_output "PASSED"
expect_output ", real time (1000 us ticks)"
expect_output "log complete: yes (every participant ended, every cycle of the cnc's output, its statistics, closed by the logger)"
expect_output "overruns (missed ticks)"
expect_output "tick jitter (wake-up - due) p50"
expect_output "limit violations: 0"
for who in "axis_sim X" "axis_sim Y" "axis_sim Z" plc_sim; do
  grep -qE "^  $who +[0-9]+ +[0-9]+ +[0-9]+ +[0-9]+ +[0-9]+ +[0-9]+ +20$" "$WORK/last.out" ||
    fail "no answer figures for $who"
done
# CI runs as root: SCHED_FIFO and locked memory for the cnc, the drives and
# the PLC, 10 above the lock-step runs' priority (tests beside it run those).
for who in cnc "axis_sim X" "axis_sim Y" "axis_sim Z" plc_sim; do
  grep -q "scheduling:.*$who SCHED_FIFO 20, memory locked" "$WORK/last.out" || fail "$who: not SCHED_FIFO 20 + locked"
done
# The statistics are in the log (lcm-spy shows them live) and hil check reads them.
expect_status 0 "$hil" check "$WORK/run/run.lcmlog"
expect_output "CHECK PASSED"
expect_output "tick jitter (wake-up - due)"

# --realtime makes a lock-step scenario real-time, written into the scenario every node reads.
expect_status 0 "$hil" run "$HIL_SOURCE/tests/integration/scenarios/expectation_windows.yaml" --realtime \
  --out "$WORK/flag" --port 7772
expect_output "PASSED"
expect_output ", real time (1000 us ticks)"
grep -q "realtime: true" "$WORK/flag/scenario.yaml" || fail "--realtime is not in the resolved scenario"

# Not root: SCHED_FIFO is refused and the memory not locked; each node says
# so (a warning event) and runs on. Whether the run then passes depends on
# the load (a watchdog may fire), so only what each node got is checked.
if command -v setpriv >/dev/null; then
  mkdir -p "$WORK/nonroot" && chmod 777 "$WORK/nonroot"
  set +e
  setpriv --reuid=65534 --regid=65534 --clear-groups "$hil" run \
    "$HIL_SOURCE/tests/integration/scenarios/expectation_windows.yaml" --realtime --out "$WORK/nonroot/run" \
    --port 7773 >"$WORK/last.out" 2>&1
  set -e
  cat "$WORK/last.out"
  for who in cnc "axis_sim X" plc_sim; do
    grep -q "scheduling:.*$who normal scheduling (SCHED_FIFO refused: Operation not permitted), memory not locked" \
      "$WORK/last.out" || fail "$who: no fallback reported"
  done
  expect_output "warning: real time: normal scheduling"
fi

# One thread cannot tick on the wall clock: refused, exit 2.
expect_status 2 "$hil" run "$HIL_SOURCE/scenarios/rig/realtime_demo.yaml" --in-process --out "$WORK/no"
expect_output "--in-process runs in lock-step only; real-time mode (run.realtime) needs the processes"
expect_status 2 "$hil" run "$HIL_SOURCE/scenarios/demo.yaml" --realtime --in-process --out "$WORK/no2"
expect_output "real-time mode (--realtime) needs the processes"
