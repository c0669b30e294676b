#!/bin/sh
# RIG-5 DPS-3: `same_path` through the whole rig. A feed hold and override
# changes leave the path as it is: the check holds. A short cut (delete
# distance to go) makes another path: the check fails, and with it the run,
# although each variant passes on its own. Where the distance stands while
# an axis moves (#DISTANCE PROG START OFF) samples are skipped.
. "$(dirname "$0")/lib.sh"

expect_status 0 "$hil" run "$HIL_SOURCE/scenarios/rig/same_path_feedhold.yaml" --out "$WORK/held" --port 7781
expect_output "scenario same_path_feedhold (2 variants): PASSED"
expect_output "compare same_path held against uninterrupted (dist_prog_start > 0.0000 mm, tolerance 1.000 µm): "
expect_output " 0 skipped, worst difference "
expect_output ": holds"
expect_output "limit violations: 0"
[ -f "$WORK/held/held/run.lcmlog" ] && [ -f "$WORK/held/uninterrupted/scenario.yaml" ] || fail "no folder per variant"
# The nodes read the variant's own timeline, never variants / compare.
grep -q "feedhold.command_w" "$WORK/held/held/scenario.yaml" || fail "held's scenario.yaml lacks its timeline"
! grep -q "feedhold.command_w" "$WORK/held/uninterrupted/scenario.yaml" || fail "uninterrupted's scenario.yaml has held's timeline"
! grep -qE "^(variants|compare):" "$WORK/held/held/scenario.yaml" || fail "a variant's scenario.yaml has variants/compare"

expect_status 1 "$hil" run "$HIL_SOURCE/tests/integration/scenarios/same_path_short_cut.yaml" --out "$WORK/short_cut" --port 7782
expect_output "scenario same_path_short_cut (2 variants): FAILED"
expect_output "  because a comparison of the variants fails"
expect_output "scenario same_path_short_cut.short_cut (RIG-5 DPS-3 DDTG-1): PASSED"
expect_output "a sample differs by more than 1.000 µm"
expect_output ": FAILS"
if grep -q "because variant" "$WORK/last.out"; then fail "a variant failed on its own: the comparison is not what failed"; fi

# #DISTANCE PROG START OFF: the samples at the distance that stood are skipped (counted), the others compared.
expect_status 0 "$hil" run "$HIL_SOURCE/tests/integration/scenarios/same_path_distance_off.yaml" --out "$WORK/off" --port 7783
expect_output "scenario same_path_distance_off (2 variants): PASSED"
grep -qE "compare same_path held against uninterrupted .* [1-9][0-9]* samples compared, [1-9][0-9]* skipped, .*: holds" \
  "$WORK/last.out" || fail "no sample skipped at the distance that stood, or the check failed"
