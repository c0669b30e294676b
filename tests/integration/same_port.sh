#!/bin/sh
# RIG-9: two rigs started on the same --port hear each other's traffic; the
# run id tells them apart. Rig a runs into axis Y's software limit on
# purpose (a drive error at cycle 1883), rig b runs the demo at the same
# time: b takes none of a's answers (no fake drive error, no cycle skipped),
# both pass, and each counts the other's messages as another run's.
. "$(dirname "$0")/lib.sh"

"$hil" run "$HIL_SOURCE/tests/integration/scenarios/y_software_limit.yaml" --out "$WORK/a" --port 7780 \
  >"$WORK/a.out" 2>&1 &
a=$!
"$hil" run "$HIL_SOURCE/scenarios/demo.yaml" --out "$WORK/b" --port 7780 >"$WORK/b.out" 2>&1 &
b=$!
status=0
wait "$a" || status=1
wait "$b" || status=1
cat "$WORK/a.out" "$WORK/b.out" | grep -v "^    \|^  [a-z|]\|^axis" || true
[ "$status" -eq 0 ] || fail "a rig on a shared port did not pass"
for run in a b; do
  grep -q "PASSED" "$WORK/$run.out" || fail "run $run did not pass"
  grep -q "^  cnc: .*AXIS_X_STATE: [0-9]* foreign run" "$WORK/$run.out" || fail "run $run did not count the other run"
done
if grep -q "drive error" "$WORK/b.out"; then fail "rig b took rig a's drive error"; fi
