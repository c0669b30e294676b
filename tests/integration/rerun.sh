#!/bin/sh
# RIG-7: `hil rerun` feeds the PLC inputs (and drive monitoring answers) of
# a recorded run into the current CNC build in lock-step: the demo reruns
# identical; a run with a drive error (the channel's error stop) too; and a
# log whose recorded setpoint was altered is caught at that cycle (the
# acceleration's last byte: the message's last 8 are the run's MAC, RIG-12).
. "$(dirname "$0")/lib.sh"

expect_status 0 "$hil" run "$HIL_SOURCE/scenarios/demo.yaml" --out "$WORK/demo" --port 7720
expect_status 0 "$hil" rerun "$WORK/demo/run.lcmlog"
expect_output "identical: "
expect_status 0 "$hil" run "$HIL_SOURCE/scenarios/monitoring/acceleration_overload.yaml" --out "$WORK/error" --port 7721
expect_status 0 "$hil" rerun "$WORK/error/run.lcmlog"
expect_output "identical: "

# Alter one recorded setpoint: the 2000th AXIS_Y_CMD message's last byte
# (the low bits of its acceleration). LCM log records: sync word, event
# number, timestamp, channel length, data length, channel, data.
perl -e '
  local $/; open(my $in, "<:raw", $ARGV[0]) or die; my $log = <$in>; my ($pos, $seen) = (0, 0);
  while ($pos < length $log) {
    my ($sync, $nhi, $nlo, $thi, $tlo, $clen, $dlen) = unpack("N7", substr($log, $pos, 28));
    die "bad sync" unless $sync == 0xEDA1DA01;
    my $channel = substr($log, $pos + 28, $clen);
    my $end = $pos + 28 + $clen + $dlen;
    if ($channel eq "AXIS_Y_CMD" && ++$seen == 2000) { substr($log, $end - 9, 1) ^= "\x01"; last; }
    $pos = $end;
  }
  open(my $out, ">:raw", $ARGV[1]) or die; print $out $log;' "$WORK/demo/run.lcmlog" "$WORK/altered.lcmlog"
expect_status 1 "$hil" rerun "$WORK/altered.lcmlog"
expect_output "differs at cycle 1999: AXIS_Y_CMD: recorded position"
