#!/bin/sh
# Golden traces (issue 35, docs/GOLDEN.md): writes tests/golden/ anew from
# this build - every scenario of scenarios/ run in-process, and the fuzz
# seeds 1 .. 8 of every program kind. Commit them with the reason when a
# change of behaviour is meant; ctest compares every run with them
# (scenarios_K_of_N, golden.fuzz_<kind>).
# Usage: scripts/golden.sh [BUILD_BIN]   (default build/bin)
set -eu
cd "$(dirname "$0")/.."
bin=$(cd "${1:-build/bin}" && pwd)
golden=tests/golden
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

rm -rf "$golden/scenarios" "$golden/fuzz"
scripts/in_netns.sh "$bin/hil" run scenarios --in-process -j2 --json "$work/results.json" --out "$work/runs" > "$work/suite.txt" ||
  { tail -5 "$work/suite.txt"; echo "golden.sh: the suite does not pass: no golden traces from a failing build" >&2; exit 1; }
python3 tests/tools/golden_scenarios.py write "$bin/hil" "$work/results.json" "$golden"
for kind in mixed lines arcs steps commands contour lift hsc; do
  "$bin/channel_fuzz" --seed 1 --runs 8 --program-kind "$kind" --golden "$golden/fuzz" --write-golden > "$work/fuzz.txt" ||
    { cat "$work/fuzz.txt"; exit 1; }
done
echo "golden.sh: fuzz traces of 8 seeds x 8 kinds; $(du -sh --apparent-size "$golden" | cut -f1) in $golden"
