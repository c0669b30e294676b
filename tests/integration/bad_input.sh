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

# RIG-3: a drive model whose closed loop would be unstable is refused.
printf 'name: x\nmachine:\n  axes:\n    - {name: X, v_max: 100, a_max: 1000, j_max: 10000, kv: 60, velocity_lag_s: 0.02, velocity_loop_order: 2, velocity_damping: 0.5}\nnc_program: "M30"\n' >"$WORK/unstable.yaml"
expect_status 2 "$hil" run "$WORK/unstable.yaml" --out "$WORK/run3" --port 7742
expect_output "axis X: drive model: the position loop is unstable"
