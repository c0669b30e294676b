#!/bin/sh
# RIG-4 (issue 19): `hil export RUN.lcmlog --csv DIR` writes one CSV file per
# channel of a rig log: headers with SI units, one row per message (the
# lock-step channels one per cycle the report states), readable by Python's
# csv module; a channel of a type it does not know and a damaged message are
# counted, not fatal; a file that is no LCM log exits 2.
. "$(dirname "$0")/lib.sh"
cd "$WORK"

expect_status 0 "$hil" run "$HIL_SOURCE/scenarios/demo.yaml" --in-process --out demo
cycles=$(sed -n 's/^log: .* (\([0-9]*\) messages, \([0-9]*\) cycles = .*/\2/p' demo/report.txt)
messages=$(sed -n 's/^log: .* (\([0-9]*\) messages, \([0-9]*\) cycles = .*/\1/p' demo/report.txt)
[ -n "$cycles" ] && [ "$cycles" -gt 100 ] || fail "no cycle count in the report"

expect_status 0 "$hil" export demo/run.lcmlog --csv csv
expect_output "exported demo/run.lcmlog: $messages messages"
expect_output "left out: 0 channel(s) of unknown type, 0 undecodable message(s)"
for ch in AXIS_X_CMD AXIS_Y_CMD AXIS_Z_CMD AXIS_X_STATE AXIS_Y_STATE AXIS_Z_STATE HLI_STATE HLI_CONTROL \
          HIL_EVENT HIL_MANIFEST HIL_PARTICIPANT HIL_SCENARIO HIL_LOG_END; do
  [ -s "csv/$ch.csv" ] || fail "no csv/$ch.csv"
done
head -1 csv/AXIS_X_CMD.csv | grep -qx "t_s,log_t_s,run_id,utime_s,cycle,axis,position_m,velocity_m_s,acceleration_m_s2" \
  || fail "AXIS_X_CMD.csv header: $(head -1 csv/AXIS_X_CMD.csv)"

CYCLES=$cycles MESSAGES=$messages python3 - <<'PY'
import csv, glob, os
cycles, messages = int(os.environ["CYCLES"]), int(os.environ["MESSAGES"])
def rows(name):
    with open(f"csv/{name}.csv", newline="") as f:
        return list(csv.DictReader(f))
total = 0
for path in glob.glob("csv/*.csv"):
    with open(path, newline="") as f:
        r = list(csv.reader(f))
    assert all(len(row) == len(r[0]) for row in r), path  # every row as wide as the header
    total += len(r) - 1
assert total == messages, (total, messages)  # every message of the log is a row
for ch in ["AXIS_X_CMD", "AXIS_Z_STATE", "HLI_STATE", "HLI_CONTROL"]:  # lock-step: one row a cycle
    assert len(rows(ch)) == cycles, (ch, len(rows(ch)), cycles)
x = rows("AXIS_X_CMD")
assert [int(r["cycle"]) for r in x] == list(range(cycles))
assert abs(float(x[-1]["t_s"]) - (cycles - 1) * 0.001) < 1e-9  # xyz_machine: 1 ms cycle
# The demo ends at X0 Y0 Z10 (mm): in m. Its contour reaches X100 mm.
last = rows("AXIS_Z_STATE")[-1]
assert abs(float(last["position_m"]) - 0.010) < 1e-6, last
assert abs(max(float(r["position_m"]) for r in x) - 0.100) < 1e-6
hli = rows("HLI_STATE")
assert hli[-1]["channel_state"] == "2" and hli[-1]["block_nr_r"] == "110", hli[-1]  # PROGRAM_END at N110
assert hli[-1]["channel_state_name"] == "PROGRAM_END", hli[-1]
assert hli[0]["axis_name[0]"] == "X" and "axis_position_r.Z_m" in hli[0]
assert abs(float(hli[-1]["axis_position_r.Z_m"]) - 0.010) < 1e-6
# The logger's seal is stamped when it is written, after everything it seals (issue 37; it was 0).
seal = rows("HIL_LOG_END")[0]
assert float(hli[-1]["log_t_s"]) <= float(seal["log_t_s"]) < 600, (hli[-1]["log_t_s"], seal["log_t_s"])
assert max(float(r["path_velocity_m_s"]) for r in hli) > 0.04  # F3000 mm/min = 0.05 m/s
scenario = rows("HIL_SCENARIO")
assert len(scenario) == 1 and "N110 M30" in scenario[0]["nc_program"], scenario[0].keys()  # multi-line, quoted
events = rows("HIL_EVENT")
assert any(e["verdict"] == "1" and e["source"] == "plc_sim" for e in events)  # a PASS
print("csv: %d messages in %d files, %d cycles" % (total, len(glob.glob("csv/*.csv")), cycles))
PY

# A channel of a type this build does not know and a damaged message (the
# 10th HLI_STATE's fingerprint) in the same log: counted, the rest exported.
perl -e '
  local $/; open(my $in, "<:raw", $ARGV[0]) or die; my $log = <$in>; my ($pos, $seen) = (0, 0);
  while ($pos < length $log) {
    my ($sync, $nhi, $nlo, $thi, $tlo, $clen, $dlen) = unpack("N7", substr($log, $pos, 28));
    die "bad sync" unless $sync == 0xEDA1DA01;
    if (substr($log, $pos + 28, $clen) eq "HLI_STATE" && ++$seen == 10) { substr($log, $pos + 28 + $clen, 1) ^= "\x80"; }
    $pos += 28 + $clen + $dlen;
  }
  my ($channel, $data) = ("SOMEONE_ELSES", "not an LCM type");
  $log .= pack("N7", 0xEDA1DA01, 0, 999999, 0, 0, length $channel, length $data) . $channel . $data;
  open(my $out, ">:raw", $ARGV[1]) or die; print $out $log;' demo/run.lcmlog odd.lcmlog
expect_status 0 "$hil" export odd.lcmlog --csv odd
expect_output "not exported: SOMEONE_ELSES (1 message(s) of a type this build does not know)"
expect_output "1 undecodable message(s) left out"
expect_output "left out: 1 channel(s) of unknown type, 1 undecodable message(s)"
[ "$(($(wc -l <odd/AXIS_X_CMD.csv) - 1))" -eq "$cycles" ] || fail "odd log: AXIS_X_CMD rows"

# Not an LCM log: exit 2, said on stderr.
echo "plain text" >notes.txt
set +e; "$hil" export notes.txt --csv bad >stdout.txt 2>stderr.txt; status=$?; set -e
[ "$status" -eq 2 ] || fail "export of a text file exited $status"
grep -q "notes.txt is not an LCM event log" stderr.txt || fail "stderr: $(cat stderr.txt)"
expect_status 2 "$hil" export demo/run.lcmlog
expect_output "--csv is required"
echo "export: OK"
