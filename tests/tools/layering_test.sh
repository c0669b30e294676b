#!/bin/sh
# Issue 35: the CNC kernel's layers are CMake libraries that see only the
# headers below them (cnc/CMakeLists.txt): a header of a higher layer does
# not compile in a lower one, its own and those below do.
# Usage: layering_test.sh CXX FLAGS_DIR   (FLAGS_DIR/<library>.includes: one folder per line)
set -eu
cxx=$1 dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
# compiles LIBRARY HEADER: 0 if a file including HEADER compiles with LIBRARY's include folders
compiles() {
  printf '#include "%s"\n' "$2" > "$work/probe.cpp"
  flags=$(sed 's/^/-I/' "$dir/$1.includes" | tr '\n' ' ')
  # shellcheck disable=SC2086
  "$cxx" -std=c++17 -fsyntax-only $flags "$work/probe.cpp" 2> "$work/err"
}
expect() {  # expect yes|no LIBRARY HEADER
  if compiles "$2" "$3"; then got=yes; else got=no; fi
  if [ "$got" = "$1" ]; then echo "ok: $3 in $2: $got"
  else echo "FAIL: $3 in $2 compiles: $got, expected $1"; head -3 "$work/err"; failures=$((failures + 1)); fi
}
expect yes hil_ipo position_profile.hpp
expect no hil_ipo block.hpp
expect no hil_ipo path_segment.hpp
expect yes hil_decoder block.hpp
expect no hil_decoder path_segment.hpp
expect yes hil_path look_ahead.hpp
expect no hil_path lift_ranges.hpp
expect no hil_path block_search.hpp
expect no hil_path path_interpolator.hpp
expect yes hil_lift lift_ranges.hpp
expect no hil_lift block_search.hpp
expect no hil_lift channel.hpp
expect yes hil_search block_search.hpp
expect no hil_search lift_ranges.hpp
expect no hil_search channel.hpp
expect yes hil_channel channel.hpp
expect no hil_channel cycle_loop.hpp
expect yes hil_cycle cycle_loop.hpp
[ "$failures" -eq 0 ] || { echo "$failures layering check(s) failed"; exit 1; }
echo "the kernel's layers hold"
