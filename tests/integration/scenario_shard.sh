#!/bin/sh
# RIG-5, RIG-9: the project's scenarios through the suite runner, one shard
# of them (ctest runs the shards side by side): in-process (these tests are
# about the CNC's functions; integration.determinism compares in-process and
# process logs), every scenario of the shard must pass, and its JUnit file
# must name exactly the shard's files: every N-th from the K-th in path order.
# A real-time scenario cannot run in-process: SKIPPED here, run as processes
# by realtime_demo.sh and fault_injection.sh.
# Issue 35: every run's log is then compared with its golden trace
# (tests/golden/, docs/GOLDEN.md) within 1e-9 mm per setpoint.
# Usage: scenario_shard.sh K/N
. "$(dirname "$0")/lib.sh"

expect_status 0 "$hil" run "$HIL_SOURCE/scenarios" --in-process --shard "$1" --junit "$WORK/junit.xml" \
  --json "$WORK/results.json" --out "$WORK/runs"
expect_output "suite: PASSED"

python3 - "$HIL_SOURCE/scenarios" "$1" "$WORK/junit.xml" "$WORK/results.json" <<'PY'
import json, pathlib, sys, xml.etree.ElementTree as ET
root, shard, junit, results = pathlib.Path(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4]
k, n = map(int, shard.split("/"))
files = sorted((p for p in root.rglob("*.yaml")), key=lambda p: p.parts)[k - 1::n]
suites = ET.parse(junit).getroot()
assert suites.tag == "testsuites", suites.tag
cases = suites.find("testsuite").findall("testcase")
named = [pathlib.Path(c.get("file")).resolve() for c in cases]
assert named == [f.resolve() for f in files], (named, files)
for case, f in zip(cases, files):
    realtime = "realtime: true" in f.read_text()
    assert case.find("failure") is None and case.find("error") is None, f
    assert (case.find("skipped") is not None) == realtime, f
    assert case.get("name") == f.stem and float(case.get("time")) > 0 or realtime, f
doc = json.load(open(results))
assert doc["counts"]["scenarios"] == len(files) and doc["counts"]["failed"] == 0, doc["counts"]
print(f"shard {shard}: {len(files)} scenario(s), JUnit and JSON agree")
PY

python3 "$HIL_SOURCE/tests/tools/golden_scenarios.py" check "$hil" "$WORK/results.json" "$HIL_SOURCE/tests/golden"
