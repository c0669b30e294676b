#!/bin/sh
# RIG-5, RIG-9: a program of 1,000,000 lines (20.9 MB) runs. It used to fail
# after 33 s with misleading errors: the CNC's manifest carried the program
# twice (42.8 MB in one LCM message), and most receivers lost fragments of
# it. Now the manifest is small, every node reads the program from the run
# folder, and the logger writes it into the log (HIL_SCENARIO). The run
# stops at run.max_time_s, which the scenario expects.
. "$(dirname "$0")/lib.sh"

perl -e '
  print "name: million_lines\nmachine: $ARGV[0]/config/xyz_machine.yaml\nnc_program: |\n";
  print "  N$_ G01 X", $_ % 2, " F1000\n" for 1 .. 1000000;
  print "run:\n  max_time_s: 0.5\nplc:\n  timeline:\n    - when: {cycle: 5}\n",
        "      set: {program_start.enable_w: true, program_start.command_w: true}\n",
        "expect:\n  - when: {time_s: 0.4}\n    channel_state: ACTIVE\n",
        "expect_events:\n  - {severity: error, id: 0}   # run.max_time_s reached\n";' "$HIL_SOURCE" >"$WORK/million.yaml"

expect_status 0 "$hil" run "$WORK/million.yaml" --out "$WORK/run" --port 7798
expect_output "PASSED"
expect_output "log complete: yes"
expect_output "expectations (plc_sim): 2 passed, 0 failed"
[ "$(wc -l <"$WORK/run/program.nc")" -eq 1000000 ] || fail "program.nc is not the whole program"
expect_status 0 "$hil" check "$WORK/run/run.lcmlog"
expect_output "CHECK PASSED"
