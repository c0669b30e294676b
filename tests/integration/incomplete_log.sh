#!/bin/sh
# RIG-4, RIG-9: `hil check` fails on a log that does not hold the whole run
# and says why: 44 % of the drives' answers dropped (it used to pass), the
# log cut short (no RUN_END, not closed by the logger), a message that does
# not decode.
. "$(dirname "$0")/lib.sh"

expect_status 0 "$hil" run "$HIL_SOURCE/tests/integration/scenarios/short_move.yaml" --out "$WORK/run" --port 7795
log="$WORK/run/run.lcmlog"
expect_status 0 "$hil" check "$log"
expect_output "CHECK PASSED"

# Rewrites the log record by record (sync word, event number, timestamp,
# channel length, data length, channel, data): $1 is perl code that decides
# per record ($channel, $n = its index on the channel, $pos = its offset in
# $log) whether to keep it, and may alter $data (not its length).
edit_log() {
  perl -e '
    my ($keep, $in_file, $out_file) = @ARGV;
    local $/; open(my $in, "<:raw", $in_file) or die; our $log = <$in>;
    open(my $out, ">:raw", $out_file) or die; our ($pos, %count) = (0);
    while ($pos < length $log) {
      my ($sync, $nhi, $nlo, $thi, $tlo, $clen, $dlen) = unpack("N7", substr($log, $pos, 28));
      die "bad sync" unless $sync == 0xEDA1DA01;
      our $channel = substr($log, $pos + 28, $clen);
      our $data = substr($log, $pos + 28 + $clen, $dlen);
      our $n = $count{$channel}++;
      my $kept = eval $keep;
      die $@ if $@;
      print $out substr($log, $pos, 28 + $clen) . $data if $kept;
      $pos += 28 + $clen + $dlen;
    }' "$1" "$log" "$2"
}

edit_log '$channel !~ /^AXIS_._STATE$/ || $n % 25 >= 11' "$WORK/thinned.lcmlog"
expect_status 1 "$hil" check "$WORK/thinned.lcmlog"
expect_output "CHECK FAILED"
grep -q "^  AXIS_X_STATE: [0-9]* of [0-9]* cycles missing (the first: 0)" "$WORK/last.out" || fail "missing cycles"

edit_log '$pos < 0.6 * length $log' "$WORK/cut.lcmlog"
expect_status 1 "$hil" check "$WORK/cut.lcmlog"
expect_output "CHECK FAILED"
expect_output "the logger did not close the log (no HIL_LOG_END)"
expect_output "no RUN_END from the cnc"

edit_log '$channel ne "HLI_STATE" || $n != 100 || (substr($data, 0, 1) ^= "\xff", 1)' "$WORK/undecodable.lcmlog"
expect_status 1 "$hil" check "$WORK/undecodable.lcmlog"
expect_output "CHECK FAILED"
expect_output "in the log messages of this run or unreadable: HLI_STATE: 1 undecodable"
grep -q "^  HLI_STATE: 1 of [0-9]* cycles missing (the first: 100)" "$WORK/last.out" || fail "the cycle of the bad message"
