#!/usr/bin/env python3
"""RIG-5 (issue 37, 4): the shipped JSON Schemas are what `hil schema` makes
from the loaders' key tables; every project scenario and machine file
validates against its schema and names it for yaml-language-server; a typo'd
key does not validate."""
import glob, os, subprocess, sys

import jsonschema
import yaml

hil, source = sys.argv[1], os.path.abspath(sys.argv[2])
# Refused by the loader on purpose (a test of that): the schema must refuse it too.
refused_on_purpose = {os.path.join(source, "tests", "integration", "scenarios", "unknown_control_field.yaml")}
failures = []
schemas = {}
for kind in ("scenario", "machine"):
    made = subprocess.run([hil, "schema", kind], check=True, capture_output=True, text=True).stdout
    path = os.path.join(source, "schemas", kind + ".schema.json")
    with open(path) as f:
        shipped = f.read()
    if made != shipped:
        failures.append(f"schemas/{kind}.schema.json is not what hil schema {kind} makes: "
                        f"build/bin/hil schema {kind} > schemas/{kind}.schema.json")
    schema = yaml.safe_load(made)  # JSON is YAML
    jsonschema.Draft202012Validator.check_schema(schema)
    schemas[kind] = jsonschema.Draft202012Validator(schema)

def check(path, kind):
    with open(path) as f:
        text = f.read()
    want = "# yaml-language-server: $schema="
    line = next((l for l in text.splitlines()[:3] if l.startswith(want)), None)
    if line is None:
        failures.append(f"{path}: no '{want}...' line among its first three")
    else:
        target = os.path.abspath(os.path.join(os.path.dirname(path), line[len(want):].strip()))
        if target != os.path.join(source, "schemas", kind + ".schema.json"):
            failures.append(f"{path}: names {target}, not schemas/{kind}.schema.json")
    errors = list(schemas[kind].iter_errors(yaml.safe_load(text)))
    if path in refused_on_purpose:
        if not errors:
            failures.append(f"{path}: refused by the loader on purpose, but it validates")
        return
    for error in errors:
        failures.append(f"{path}: {'.'.join(map(str, error.absolute_path))}: {error.message}")

scenario_files = sorted(glob.glob(os.path.join(source, "scenarios", "**", "*.yaml"), recursive=True) +
                        glob.glob(os.path.join(source, "tests", "integration", "scenarios", "*.yaml")))
machine_files = sorted(glob.glob(os.path.join(source, "config", "*.yaml")))
for path in scenario_files:
    check(path, "scenario")
for path in machine_files:
    check(path, "machine")

# A typo'd key, at the top, in an axis, in an expectation, in a PLC step's writes.
for typo in ({"name": "x", "nc_programm": "M30"},
             {"machine": {"axes": [{"name": "X", "v_maxx": 1}]}},
             {"expect": [{"when": {"chanel_state": "ERROR"}}]},
             {"plc": {"timeline": [{"when": {"cycle": 1}, "set": {"program_start.comand_w": True}}]}}):
    if schemas["scenario"].is_valid(typo):
        failures.append(f"a typo validates: {typo}")

for failure in failures:
    print("FAIL:", failure)
print(f"{len(scenario_files)} scenario files, {len(machine_files)} machine files checked against schemas/: "
      f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
