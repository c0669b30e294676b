#!/bin/sh
# RIG-5, RIG-9 (issue 37, 2 and 6): a failed run says its root cause first
# (a drive's or the CNC's error with the NC line and the scenario file's
# line, before "n expectation(s) failed"), in the report, the suite's table
# and JUnit; the counts line adds up; the suite lists failures first, JUnit's
# timestamp is its start; -k, -x, --lf and --list choose what runs.
. "$(dirname "$0")/lib.sh"
cd "$WORK"
mkdir -p suite
sed -e "s|^machine: .*|machine: $HIL_SOURCE/config/xyz_machine.yaml|" \
  "$HIL_SOURCE/tests/integration/scenarios/short_move.yaml" >suite/a_short_move.yaml
cp suite/a_short_move.yaml suite/b_short_move_again.yaml
# Y passes its software limit switch in N20: nothing in the scenario expects it.
cat >suite/z_limit_hit.yaml <<'YAML'
name: limit_hit
requirements: [RIG-9]
machine:
  name: xy
  cycle_time_us: 1000
  axes:
    - {name: X, v_max: 250, a_max: 2000, j_max: 40000, kv: 40, velocity_lag_s: 0.002}
    - {name: Y, v_max: 250, a_max: 2000, j_max: 40000, kv: 40, velocity_lag_s: 0.002,
       swe_neg: -10, swe_pos: 40, swe_toleranz: 0.1}
nc_program: |
  N10 G01 X20 F1200
  N20 Y60 F3000
  N30 M30
plc:
  timeline:
    - when: {cycle: 1}
      set: {program_start.enable_w: true, program_start.command_w: true}
expect:
  - when: {channel_state: PROGRAM_END}
YAML

expect_status 1 "$hil" run suite/z_limit_hit.yaml --in-process --out one
first=$(grep -m1 "  because" last.out)
case "$first" in
  *"axis_sim Y error (P-AXIS-00178)"*) ;;
  *) fail "the first because line is not the drive's error: $first" ;;
esac
expect_output "because cnc error axis Y at nc_program line 2 (scenario file line 12) N20"
expect_output "because limit violation: axis Y commanded position"
expect_output "expectations (plc_sim): 0 passed, 3 failed of 3 verdict(s): the scenario's 1 and 2 'no unexpected error'"
grep -n "because" last.out | tail -1 | grep -q "offline check" || fail "the consequences do not come last"
# report.html tells the same story in the same order: the drive's error
# first, the CNC's next, the failed expectations after them.
python3 - one/report.html <<'PY' || fail "report.html does not put the root cause first"
import html, re, sys
text = html.unescape(re.sub(r"<[^>]+>", " ", open(sys.argv[1], encoding="utf-8").read()))
places = [text.find(s) for s in ("axis_sim Y error (P-AXIS-00178)", "cnc error axis Y", "expectation")]
assert -1 not in places and places == sorted(places), places
PY

before=$(date +%s)
expect_status 1 "$hil" run suite --in-process --out runs --junit junit.xml
expect_output "3 scenario(s): 2 passed, 1 failed, 0 error(s), 0 skipped"
row=$(grep -m1 "^suite/" last.out)
case "$row" in
  "suite/z_limit_hit.yaml "*FAILED*"axis_sim Y error (P-AXIS-00178)"*) ;;
  *) fail "the first row is not the failure with its root cause: $row" ;;
esac
grep -o 'href="[^"]*report.html"' runs/report.html | head -1 | grep -q z_limit_hit || fail "the page does not list the failure first"
python3 - "$before" <<'PY'
import sys, time, xml.etree.ElementTree as ET
s = ET.parse("junit.xml").getroot().find("testsuite")
started = time.mktime(time.strptime(s.get("timestamp"), "%Y-%m-%dT%H:%M:%S"))
assert int(sys.argv[1]) - 1 <= started <= int(sys.argv[1]) + 2, (s.get("timestamp"), sys.argv[1])
f = [c for c in s.findall("testcase") if c.get("name") == "z_limit_hit"][0].find("failure")
assert f.get("message").startswith("axis_sim Y error (P-AXIS-00178)"), f.get("message")
PY
grep -qx "suite/z_limit_hit.yaml" .hil/last-failed || fail "--lf record: $(cat .hil/last-failed)"

# --list: what would run, nothing runs.
expect_status 0 "$hil" run suite --list -k again
expect_output "suite/b_short_move_again.yaml  short_move  [RIG-9]"
expect_output "1 scenario(s)"
expect_status 0 "$hil" run suite --list -k SHORT -k "not again"
expect_output "suite/a_short_move.yaml"
expect_output "1 scenario(s)"
expect_status 0 "$hil" run suite --list -k limit_hit
expect_output "suite/z_limit_hit.yaml  limit_hit"

# --lf runs the one that failed; once it passes, the record forgets it.
expect_status 1 "$hil" run suite --lf --in-process --out runs_lf
expect_output "1 scenario(s): 0 passed, 1 failed"
sed -i 's/swe_pos: 40,/swe_pos: 100,/' suite/z_limit_hit.yaml
expect_status 0 "$hil" run suite --lf --in-process --out runs_lf2
expect_output "1 scenario(s): 1 passed"
[ ! -s .hil/last-failed ] || fail "a passed scenario stayed in the record"
expect_status 0 "$hil" run suite --lf --list
expect_output "--lf: no failures recorded in .hil/last-failed: running all"
expect_output "3 scenario(s)"

# -x: the first failure stops the suite, the rest SKIPPED.
sed -e "s|X: 1}|X: 99}|" suite/a_short_move.yaml >suite/a_short_move.yaml.new && mv suite/a_short_move.yaml.new suite/a_short_move.yaml
expect_status 1 "$hil" run suite -x --in-process --out runs_x
expect_output "3 scenario(s): 0 passed, 1 failed, 0 error(s), 2 skipped"
expect_output "not run: -x stops the suite at its first failure"
echo "suite selection: ok"
