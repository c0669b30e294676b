#!/bin/sh
# RIG-6, RIG-9 (issue 33): the cnc dies mid-run (SIGKILL at cycle 1000, by
# hil_inject). Every other node notices on its own that the CNC is gone,
# 10 s after its last sign of life (docs/RELIABILITY.md), says so and exits
# 2; none is left for hil run to kill as hung. axis_sim X used to be: the
# drives and the PLC counted the logger's heartbeat as a sign of the run and
# waited 10 s after the logger, and hil run gave the node it waited for
# after the logger only the logger's 10 s. Lock-step and real-time mode.
. "$(dirname "$0")/lib.sh"

bin="$WORK/bin"
mkdir -p "$bin"
for exe in hil axis_sim plc_sim hil_logger; do ln -s "$HIL_BIN/$exe" "$bin/$exe"; done
# A wrapper that leaves the cnc's pid where hil_inject finds it.
printf '#!/bin/sh\necho $$ >"%s/cnc.pid"\nexec "%s/cnc" "$@"\n' "$WORK" "$HIL_BIN" >"$bin/cnc"
chmod +x "$bin/cnc"

# Seconds since midnight of a time of day (HH:MM:SS.fff).
seconds_of_day() { echo "$1" | awk -F: '{ printf "%.3f\n", $1 * 3600 + $2 * 60 + $3 }'; }

# run_killing SCENARIO PORT NAME: the scenario with the cnc killed at cycle
# 1000; the run folder is $WORK/NAME. It must FAIL because of the kill, and
# each node must have ended itself 10 s (+ its polling, + a loaded CI
# machine's slack) after the kill.
run_killing() {
  rm -f "$WORK/cnc.pid"
  (
    "$HIL_BIN/hil_inject" --url "udpm://239.255.76.67:$2?ttl=0" --at-cycle 1000 --kill-pid-file "$WORK/cnc.pid" \
      >"$WORK/inject.out" 2>&1 && date +%H:%M:%S.%N >"$WORK/killed_at"
  ) &
  injector=$!
  expect_status 1 "$bin/hil" run "$HIL_SOURCE/scenarios/$1" --out "$WORK/$3" --port "$2" --bin-dir "$bin"
  wait "$injector" || { cat "$WORK/inject.out"; fail "hil_inject did not act"; }
  expect_output "FAILED"
  expect_output "  because cnc exited with status 137"
  for node in logger "axis_sim X" "axis_sim Y" "axis_sim Z" plc_sim; do
    expect_output "  because $node exited with status 2"
  done
  expect_output "exit status: cnc 137, logger 2, axis_sim X 2, axis_sim Y 2, axis_sim Z 2, plc_sim 2"
  ! grep -q "hung" "$WORK/last.out" || fail "a node was left hung"
  killed=$(seconds_of_day "$(cat "$WORK/killed_at")")
  for out in logger axis_sim_X axis_sim_Y axis_sim_Z plc_sim; do
    case $out in
      logger) said="no message of the run for 10 s and no RUN_END from the CNC: log closed early" ;;
      *) said="the CNC is gone: nothing from it for 10 s after cycle" ;;
    esac
    line=$(grep -F "$said" "$WORK/$3/$out.out") || { cat "$WORK/$3/$out.out"; fail "$out: does not say the CNC is gone"; }
    at=$(seconds_of_day "$(echo "$line" | sed 's/^\[\([0-9:.]*\)\].*/\1/')")
    awk -v at="$at" -v killed="$killed" -v who="$out" 'BEGIN {
      d = at - killed; if (d < 0) d += 86400
      printf "%s: gone %.2f s after the kill\n", who, d
      exit !(d >= 9.5 && d <= 11.5) }' || fail "$out did not end 10 s after the kill"
  done
}

run_killing demo.yaml 7860 lockstep
run_killing rig/realtime_demo.yaml 7861 realtime
expect_output ", real time (1000 us ticks)"
