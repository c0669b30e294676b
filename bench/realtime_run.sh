#!/bin/sh
# RIG-6: the rig in real-time mode for a while: 3 axes at 1 kHz (the CNC
# ticks on CLOCK_MONOTONIC, the nodes under SCHED_FIFO with locked memory
# where allowed), a program of round trips of every axis that runs about
# DURATION seconds. Prints the CNC's tick jitter (p50, p99, max), the
# overruns (missed ticks) and each participant's answers, with the load and
# the machine. The goal (issue 18): 0 missed ticks, p99 jitter <= 100 us.
# Asserts nothing; the figures go into docs/PERFORMANCE.md.
# Usage (as root, for the private network namespace and SCHED_FIFO):
#   scripts/in_netns.sh bench/realtime_run.sh [DURATION_S] [build/bin] [CPU] [poll]
# "poll": hold /dev/cpu_dma_latency at 0 while the run lasts (PM QoS, as
# cyclictest does): an idle CPU then polls instead of halting, so a timer
# wakes it without a halt and a VM exit. Every idle CPU then spins.
# WATCHDOG_CYCLES (default 20, the machine default): every drive's and the
# PLC's watchdog; a larger one lets a run go on through a stall that would
# stop it, so that the jitter of the whole duration is measured (the
# longest gap says how long the stall was). BENCH_OUT=DIR keeps the run
# folder (the log holds HIL_RT_STATS every second).
set -eu
duration=${1:-600}
bin=$(cd "${2:-build/bin}" && pwd)
cpu=${3:-1}
idle=${4:-halt}
watchdog=${WATCHDOG_CYCLES:-20}
if [ -n "${BENCH_OUT:-}" ]; then
  work=$BENCH_OUT && mkdir -p "$work"
else
  work=$(mktemp -d) && trap 'rm -rf "$work"' EXIT
fi

# A round trip X, Y, Z 0 -> 150 mm -> 0 at F9000: ~3.65 s (hil's report says the run's length).
trips=$(( (duration * 100 + 364) / 365 ))
[ "$trips" -ge 1 ] || trips=1
{
  echo "name: realtime_run"
  echo "machine:"
  echo "  cycle_time_us: 1000"
  echo "  axes:"
  for a in X Y Z; do
    echo "    - {name: $a, v_max: 250, v_rapid: 250, a_max: 2000, j_max: 40000, kv: 40, velocity_lag_s: 0.002,"
    echo "       dyn_monitoring_a_warn: 1500, dyn_monitoring_a_err: 2000, slep_max: 0.5, watchdog_cycles: $watchdog}"
  done
  echo "  plc_watchdog_cycles: $watchdog"
  echo "nc_program: |"
  echo "  N10 \$FOR P1 = 1, $trips, 1"
  echo "  N20 G01 X150 Y150 Z150 F9000"
  echo "  N30 X0 Y0 Z0"
  echo "  N40 \$ENDFOR"
  echo "  N99 M30"
  echo "run: {realtime: true, max_time_s: $(( duration * 2 + 30 )), settle_time_s: 0.1}"
  echo "plc:"
  echo "  timeline:"
  echo "    - when: {cycle: 5}"
  echo "      set: {program_start.enable_w: true, program_start.command_w: true}"
  echo "    - when: {channel_state: ACTIVE}"
  echo "      set: {program_start.command_w: false}"
  echo "expect:"
  echo "  - when: program_end"
  echo "    axis_position_mm: {X: 0, Y: 0, Z: 0}"
} > "$work/realtime_run.yaml"

echo "machine: $(nproc) CPUs, $(uname -r), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
if [ "$idle" = poll ]; then
  exec 3>/dev/cpu_dma_latency   # the request holds while the file is open
  printf '\000\000\000\000' >&3
  echo "idle: polling (/dev/cpu_dma_latency held at 0 us)"
else
  echo "idle: as configured ($(cat /sys/devices/system/cpu/cpuidle/current_driver 2>/dev/null || echo '?'))"
fi
echo "watchdog: $watchdog cycles (drives and PLC)"
echo "real time for ~${duration} s: $trips round trips, the cnc, drives and PLC on CPU $cpu"
status=0
rm -rf "$work/run"
"$bin/hil" run "$work/realtime_run.yaml" --out "$work/run" --cpu "$cpu" > "$work/report" 2>&1 || status=$?
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
grep -E "^scenario |^  because |^LCM: |^log: |^log complete|^real time: |^  scheduling|^  answers|^  axis_sim|^  plc_sim|^limit violations" "$work/report"
[ "$status" -eq 0 ] || { echo "hil run exited with $status"; cat "$work/report" | head -40; }
exit "$status"
