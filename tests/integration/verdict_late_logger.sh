#!/bin/sh
# RIG-9: the verdict does not depend on timing. The logger comes up 0.3 s
# after the others (it used to miss their READY, stop at the CNC's RUN_END
# and lose the PLC's verdicts: a scenario whose only expectation cannot hold
# PASSED). A failing expectation FAILS the run with plc_sim's exit status 0;
# a plc_sim that exits 1 FAILS it although every expectation passed.
. "$(dirname "$0")/lib.sh"
scenarios="$HIL_SOURCE/tests/integration/scenarios"

bin="$WORK/bin"
mkdir -p "$bin"
for exe in hil cnc axis_sim plc_sim; do ln -s "$HIL_BIN/$exe" "$bin/$exe"; done
printf '#!/bin/sh\nsleep 0.3\nexec "%s/hil_logger" "$@"\n' "$HIL_BIN" >"$bin/hil_logger"
chmod +x "$bin/hil_logger"
sed -e "s|X: 1}|X: 99}|" -e "s|^machine: .*|machine: $HIL_SOURCE/config/xyz_machine.yaml|" \
  "$scenarios/short_move.yaml" >"$WORK/impossible.yaml"

expect_status 1 "$bin/hil" run "$WORK/impossible.yaml" --out "$WORK/impossible" --port 7750 --bin-dir "$bin"
expect_output "FAILED"
expect_output "  because 1 expectation(s) failed"
expect_output "expectations (plc_sim): 0 passed, 1 failed of 1 verdict(s): the scenario's 1"
expect_output "plc_sim 0"

expect_status 0 "$bin/hil" run "$scenarios/short_move.yaml" --out "$WORK/late" --port 7751 --bin-dir "$bin"
expect_output "PASSED"
expect_output "log complete: yes"

rm "$bin/plc_sim"
printf '#!/bin/sh\n"%s/plc_sim" "$@"\nexit 1\n' "$HIL_BIN" >"$bin/plc_sim"
chmod +x "$bin/plc_sim"
expect_status 1 "$bin/hil" run "$scenarios/short_move.yaml" --out "$WORK/crash" --port 7752 --bin-dir "$bin"
expect_output "FAILED"
expect_output "  because plc_sim exited with status 1"
expect_output "expectations (plc_sim): 1 passed, 0 failed"
