#!/bin/sh
# Issue 17: how fast the whole rig runs in lock-step, for 1, 3 and 6 axes,
# as separate processes over LCM (RIG-1, RIG-6) and in-process. Prints
# cycles/s and x real time (simulated time / wall time of `hil run`'s run:
# from starting the nodes to the last one's end, handshakes included), and
# the CPU time the run cost per cycle. Asserts nothing.
# Usage (as root, for the private network namespace):
#   scripts/in_netns.sh bench/rig_speed.sh [build/bin] [repeats]
set -eu
bin=$(cd "${1:-build/bin}" && pwd)
repeats=${2:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

scenario() {  # scenario N AXES...: ~10 s of moves of every axis, a round trip per 2 s
  n=$1; shift
  file="$work/axes_$n.yaml"
  {
    echo "name: rig_speed_$n"
    echo "machine:"
    echo "  cycle_time_us: 1000"
    echo "  axes:"
    for a in "$@"; do
      echo "    - {name: $a, v_max: 250, v_rapid: 250, a_max: 2000, j_max: 40000, kv: 40, velocity_lag_s: 0.002,"
      echo "       dyn_monitoring_a_warn: 1500, dyn_monitoring_a_err: 2000, slep_max: 0.5}"
    done
    echo "nc_program: |"
    there="" back=""
    for a in "$@"; do there="$there ${a}150"; back="$back ${a}0"; done
    for i in 1 2 3 4 5; do
      echo "  N${i}0 G01$there F9000"
      echo "  N${i}5$back"
    done
    echo "  N99 M30"
    echo "run: {max_time_s: 30, settle_time_s: 0.1}"
    echo "plc:"
    echo "  timeline:"
    echo "    - when: {cycle: 5}"
    echo "      set: {program_start.enable_w: true, program_start.command_w: true}"
    echo "    - when: {channel_state: ACTIVE}"
    echo "      set: {program_start.command_w: false}"
    echo "expect:"
    echo "  - when: program_end"
    echo "    block_nr_r: 99"
  } >"$file"
  echo "$file"
}

# measure FILE MODE-FLAGS...: one line per repeat
measure() {
  file=$1; shift
  for r in $(seq "$repeats"); do
    out="$work/run"
    rm -rf "$out"
    /usr/bin/time -f "%U %S" -o "$work/time" "$bin/hil" run "$file" --out "$out" "$@" >"$work/report" 2>&1 || {
      cat "$work/report"; echo "rig_speed: the run failed" >&2; exit 1; }
    line=$(grep "x real time" "$work/report")
    cycles=$(echo "$line" | sed 's/.*messages, \([0-9]*\) cycles.*/\1/')
    wall=$(echo "$line" | sed 's/.* in \([0-9.e-]*\) s wall.*/\1/')
    cpu=$(awk '{print $1 + $2}' "$work/time")
    awk -v c="$cycles" -v w="$wall" -v cpu="$cpu" -v r="$r" 'BEGIN {
      printf "    run %d: %6d cycles in %7.3f s wall: %8.0f cycles/s, %6.1f x real time; CPU (hil and its nodes, plots included) %.2f s\n",
             r, c, w, c / w, c / 1000 / w, cpu }'
  done
}

echo "rig_speed: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), $(date -u +%Y-%m-%dT%H:%MZ)"
for set in "1 X" "3 X Y Z" "6 X Y Z A B C"; do
  # shellcheck disable=SC2086
  file=$(scenario $set)
  n=${set%% *}
  echo "$n axes, separate processes over LCM udpm (lock-step):"
  measure "$file" --port 7790
  echo "$n axes, in-process (--in-process):"
  measure "$file" --in-process
done
