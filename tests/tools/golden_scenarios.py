#!/usr/bin/env python3
"""Golden traces of the scenario runs of a suite (issue 35, docs/GOLDEN.md).

  golden_scenarios.py write|check HIL RESULTS_JSON GOLDEN_DIR

For each run in the suite's --json results (of scenarios in this project,
GOLDEN_DIR its tests/golden) (skipped real-time scenarios
aside), each log under its run folder: a scenario's own run.lcmlog is
GOLDEN_DIR/<scenario file less .yaml>.trace.xz, a variant's
<variant>/run.lcmlog is GOLDEN_DIR/<scenario file less .yaml>/<variant>.trace.xz.
`write` writes them with `hil golden`; `check` compares each with
`hil compare` (within 1e-9 mm) and exits 1 if any differs or is missing,
printing its differences."""
import json
import pathlib
import subprocess
import sys


def logs_of(run, golden):
    # The scenario's path in the project (GOLDEN_DIR is tests/golden in it).
    project = golden.resolve().parent.parent
    scenario = pathlib.Path(run["scenario_file"]).resolve().relative_to(project)
    stem = golden / scenario.with_suffix("")
    root = pathlib.Path(run["run_dir"])
    for log in sorted(root.rglob("run.lcmlog")):
        rel = log.parent.relative_to(root)
        own = rel == pathlib.Path(".")
        yield log, (stem.with_suffix(".trace.xz") if own else stem / f"{rel}.trace.xz"), \
            str(scenario) + ("" if own else f", variant {rel}")


def main():
    mode, hil, results, golden = sys.argv[1], sys.argv[2], sys.argv[3], pathlib.Path(sys.argv[4])
    runs = [r for r in json.load(open(results))["runs"] if r["verdict"] != "SKIPPED"]
    count, bad = 0, []
    for run in runs:
        for log, trace, source in logs_of(run, golden):
            count += 1
            if mode == "write":
                trace.parent.mkdir(parents=True, exist_ok=True)
                subprocess.run([hil, "golden", str(log), "--out", str(trace), "--comment", source], check=True,
                               stdout=subprocess.DEVNULL)
                continue
            if not trace.exists():
                bad.append(f"{run['scenario_file']}: no golden trace {trace} (scripts/golden.sh writes it)")
                continue
            r = subprocess.run([hil, "compare", str(trace), str(log)], capture_output=True, text=True)
            if r.returncode != 0:
                bad.append(f"{run['scenario_file']} ({log.parent.name}) against {trace}:\n" + r.stdout + r.stderr)
    for b in bad:
        print("GOLDEN " + b)
    verb = "written" if mode == "write" else "compared"
    print(f"golden traces: {count} {verb}, {len(bad)} differ or missing")
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
