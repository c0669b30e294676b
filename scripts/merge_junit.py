#!/usr/bin/env python3
"""Merges JUnit XML files (e.g. one per `hil run --shard K/N`) into one.

Usage: merge_junit.py OUT.xml IN.xml [IN.xml ...]

Every <testsuite> of the inputs goes into one <testsuites> whose tests,
failures, errors, skipped and time are the sums. Standard library only.
"""
import sys
import xml.etree.ElementTree as ET


def main(argv):
    if len(argv) < 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    merged = ET.Element("testsuites", name="hil")
    totals = {"tests": 0, "failures": 0, "errors": 0, "skipped": 0}
    time = 0.0
    for path in argv[2:]:
        try:
            root = ET.parse(path).getroot()
        except (OSError, ET.ParseError) as e:
            print(f"merge_junit: {path}: {e}", file=sys.stderr)
            return 2
        for suite in ([root] if root.tag == "testsuite" else root.findall("testsuite")):
            merged.append(suite)
            for key in totals:
                totals[key] += int(suite.get(key, "0"))
            time += float(suite.get("time", "0"))
    for key, value in totals.items():
        merged.set(key, str(value))
    merged.set("time", f"{time:.3f}")
    ET.ElementTree(merged).write(argv[1], encoding="UTF-8", xml_declaration=True)
    print(f"{argv[1]}: {totals['tests']} tests, {totals['failures']} failures, {totals['errors']} errors, "
          f"{totals['skipped']} skipped from {len(argv) - 2} file(s)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
