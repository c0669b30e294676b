#!/bin/sh
# Bad input never starts the rig: a clear message and exit status 2.
. "$(dirname "$0")/lib.sh"
scenarios="$HIL_SOURCE/tests/integration/scenarios"

expect_status 2 "$hil" run "$scenarios/unknown_control_field.yaml" --out "$WORK/run" --port 7740
expect_output "program_start.comand_w"

printf 'name: x\nmachine: no_such_machine.yaml\nnc_program: "M30"\n' >"$WORK/missing_machine.yaml"
expect_status 2 "$hil" run "$WORK/missing_machine.yaml" --out "$WORK/run2" --port 7741
expect_output "no_such_machine.yaml"

printf 'not an LCM log\n' >"$WORK/not_a_log"
expect_status 2 "$hil" check "$WORK/not_a_log"
expect_output "not an LCM"

# RIG-11 (issue 33): a machine limit outside physical sense is refused,
# naming the machine file, the key, the value and the range (it used to run
# and time out, the axis never moving).
sed 's/j_max: 30000/j_max: 1e-320/' "$HIL_SOURCE/config/xyz_machine.yaml" >"$WORK/tiny_jerk_machine.yaml"
printf 'name: x\nmachine: tiny_jerk_machine.yaml\nnc_program: "M30"\n' >"$WORK/tiny_jerk.yaml"
expect_status 2 "$hil" run "$WORK/tiny_jerk.yaml" --out "$WORK/run11" --port 7753
expect_output "tiny_jerk_machine.yaml: machine.axes[2].j_max: must be a number within 0.1 .. 1e+09 mm/s^3, not 1e-320"

# RIG-3: a drive model whose closed loop would be unstable is refused.
printf 'name: x\nmachine:\n  axes:\n    - {name: X, v_max: 100, a_max: 1000, j_max: 10000, kv: 60, velocity_lag_s: 0.02, velocity_loop_order: 2, velocity_damping: 0.5}\nnc_program: "M30"\n' >"$WORK/unstable.yaml"
expect_status 2 "$hil" run "$WORK/unstable.yaml" --out "$WORK/run3" --port 7742
expect_output "axis X: drive model: the position loop is unstable"

# RIG-5: a typo'd key is refused, not ignored (here it would switch the
# following error monitoring of axis Y off), naming file, path and the key meant.
sed '0,/slep_max/! {0,/slep_max/ s/slep_max/slep_mx/}' "$HIL_SOURCE/config/xyz_machine.yaml" >"$WORK/typo_machine.yaml"
printf 'name: x\nmachine: typo_machine.yaml\nnc_program: "M30"\n' >"$WORK/typo.yaml"
expect_status 2 "$hil" run "$WORK/typo.yaml" --out "$WORK/run4" --port 7743
expect_output "typo_machine.yaml: machine.axes[1].slep_mx: unknown key, did you mean slep_max?"
printf 'name: x\nmachine: %s\nnc_program: "M30"\nexpectations:\n  - when: program_end\n' \
  "$HIL_SOURCE/config/xyz_machine.yaml" >"$WORK/expectations.yaml"
expect_status 2 "$hil" run "$WORK/expectations.yaml" --out "$WORK/run5" --port 7744
expect_output "expectations: unknown key, did you mean expect?"

# Numbers that are not finite, a directory for a file, binary in an NC file.
printf 'name: x\nmachine: %s\nnc_program: "M30"\nrun: {max_time_s: .nan}\n' \
  "$HIL_SOURCE/config/xyz_machine.yaml" >"$WORK/nan.yaml"
expect_status 2 "$hil" run "$WORK/nan.yaml" --out "$WORK/run6" --port 7745
expect_output "nan.yaml: run.max_time_s: must be a number > 0 and <= 1e+06, not .nan"
# A folder is a suite (docs/SUITES.md): one without scenario files is refused.
mkdir -p "$WORK/folder"
expect_status 2 "$hil" run "$WORK/folder" --out "$WORK/run7" --port 7746
expect_output "folder: a folder without scenario files (*.yaml)"
printf 'N10 G01 X1 F600\nN20 X\0002\nN30 M30\n' >"$WORK/binary.nc"
printf 'name: x\nmachine: %s\nnc_file: binary.nc\n' "$HIL_SOURCE/config/xyz_machine.yaml" >"$WORK/binary.yaml"
expect_status 2 "$hil" run "$WORK/binary.yaml" --out "$WORK/run8" --port 7747
expect_output "binary.nc: line 2: byte 0x00 (NUL) is not text"
# RIG-5 (issue 19): a range no value fits, and a stop condition nobody has,
# are refused before the rig starts, naming the key (and the name meant).
printf 'name: x\nmachine: %s\nnc_program: "M30"\nexpect:\n  - never: {path_velocity_mm_s: {min: 5, max: 4}}\n' \
  "$HIL_SOURCE/config/xyz_machine.yaml" >"$WORK/range.yaml"
expect_status 2 "$hil" run "$WORK/range.yaml" --out "$WORK/run9" --port 7748
expect_output "range.yaml: expect[0].never.path_velocity_mm_s: min 5 is more than max 4"
printf 'name: x\nmachine: %s\nnc_program: "M30"\nexpect:\n  - when: {stop_conditions_r: {contains: [FEED_HOLD]}}\n' \
  "$HIL_SOURCE/config/xyz_machine.yaml" >"$WORK/stop_name.yaml"
expect_status 2 "$hil" run "$WORK/stop_name.yaml" --out "$WORK/run10" --port 7749
expect_output "expect[0].when.stop_conditions_r.contains[0]: unknown stop condition 'FEED_HOLD', did you mean FEEDHOLD?"
# KRN-8 (issue 34): the NC program decodes as a whole before any process
# starts: a refused one exits 2 with its line and column and the reason;
# `hil validate` checks without running.
printf 'name: x\nmachine: %s\nnc_program: |\n  N10 G01 X1 F600\n    N20 G41 X2\n  N30 M30\n' \
  "$HIL_SOURCE/config/xyz_machine.yaml" >"$WORK/refused_nc.yaml"
expect_status 2 "$hil" run "$WORK/refused_nc.yaml" --out "$WORK/run11" --port 7750
expect_output "refused_nc.yaml: nc_program line 2 (scenario file line 5) column 7 (N20), error 20131: G41 tool radius compensation (left) is not supported by this rig"
[ ! -e "$WORK/run11/run.lcmlog" ] || fail "a refused program started the rig"
expect_status 2 "$hil" validate "$WORK/refused_nc.yaml" "$HIL_SOURCE/scenarios/demo.yaml"
expect_output "scenarios/demo.yaml: ok"
expect_output "refused_nc.yaml: nc_program line 2 (scenario file line 5) column 7 (N20)"
expect_status 0 "$hil" validate "$HIL_SOURCE/scenarios/programs/planes_g18_g19.yaml"
