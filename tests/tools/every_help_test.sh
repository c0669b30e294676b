#!/bin/sh
# Issue 37 (9): every executable of the build answers --help (exit 0) and
# points at the docs, and so does each subcommand's --help; unit_tests is
# Catch2's runner.
set -u
bin=$1
status=0
for exe in "$bin"/*; do
  [ -x "$exe" ] && [ -f "$exe" ] || continue
  name=$(basename "$exe")
  [ "$name" = unit_tests ] && continue
  out=$(timeout 20 "$exe" --help 2>&1)
  code=$?
  if [ "$code" -ne 0 ]; then echo "FAIL: $name --help exited $code: $out" | head -3; status=1; continue; fi
  case "$out" in
    *"docs/"*) echo "$name --help: ok" ;;
    *) echo "FAIL: $name --help does not point at the docs"; status=1 ;;
  esac
  # Its subcommands (hil run, hil spy, ...), each with its own --help.
  subs=$(printf '%s\n' "$out" | sed -n '/^Subcommands:/,/^$/p' | sed -n 's/^  \([a-z][a-z_-]*\) .*/\1/p')
  for sub in $subs; do
    sub_out=$(timeout 20 "$exe" "$sub" --help 2>&1)
    code=$?
    if [ "$code" -ne 0 ]; then echo "FAIL: $name $sub --help exited $code"; status=1; continue; fi
    case "$sub_out" in
      *"docs/"*) echo "$name $sub --help: ok" ;;
      *) echo "FAIL: $name $sub --help does not point at the docs"; status=1 ;;
    esac
  done
done
exit $status
