#!/bin/sh
# Issue 36 (KRN-6, KRN-9): the CAM corpus (tests/programs) through the whole
# rig three ways: as written, with G261 (#CONTOUR MODE [DEV PATH_DEV=0.01])
# and with #HSC ON [BSPLINE PATH_DEV=0.01 MERGE=1], one line added after the
# first G90. Prints the verdict time (s, the run's last cycle), the ideal
# (bench/program_ideal.py) and the limit violations. Asserts nothing.
# Usage: bench/cam_programs.sh [PROGRAM ..]  (names in tests/programs; run from the worktree)
set -eu
programs=${*:-surfacing_3d engraving plasma_profile mixed_transitions radius_arcs}
work=$(mktemp -d)
printf '%-20s %9s %9s %9s %9s %12s\n' program ideal_s plain_s g261_s hsc_s hsc/ideal
for p in $programs; do
  src=tests/programs/$p.nc
  ideal=$(python3 bench/program_ideal.py "$src" | awk '{print $2}')
  line="$p $ideal"
  for way in plain g261 hsc; do
    case $way in
      plain) cp "$src" "$work/$p.$way.nc" ;;
      g261) awk '{print} /G90/ && !d {print "#CONTOUR MODE [DEV PATH_DEV=0.01]"; print "G261"; d=1}' "$src" > "$work/$p.$way.nc" ;;
      hsc) awk '{print} /G90/ && !d {print "#HSC ON [BSPLINE PATH_DEV=0.01 MERGE=1]"; d=1}' "$src" > "$work/$p.$way.nc" ;;
    esac
    sed -e "s#^machine: .*#machine: $PWD/config/xyz_machine.yaml#" -e "s#^nc_file: .*#nc_file: $work/$p.$way.nc#" \
      "scenarios/programs/$p.yaml" > "$work/$p.$way.yaml"
    out=$(scripts/in_netns.sh build/bin/hil run "$work/$p.$way.yaml" --in-process --out "$work/run_${p}_$way" 2>&1 || true)
    cycle=$(printf '%s\n' "$out" | sed -n 's/.*cycle \([0-9]*\) \[plc_sim\] info: PASS.*/\1/p' | tail -1)
    violations=$(printf '%s\n' "$out" | sed -n 's/^limit violations: \([0-9]*\).*/\1/p')
    [ -n "$cycle" ] || cycle=FAIL
    line="$line $cycle/$violations"
  done
  echo "$line"
done | awk '{
  split($3, a, "/"); split($4, b, "/"); split($5, c, "/");
  printf "%-20s %9.1f %9s %9s %9s %12s\n", $1, $2,
    a[1] == "FAIL" ? "FAIL" : sprintf("%.1f", a[1] / 1000),
    b[1] == "FAIL" ? "FAIL" : sprintf("%.1f", b[1] / 1000),
    c[1] == "FAIL" ? "FAIL" : sprintf("%.1f", c[1] / 1000),
    c[1] == "FAIL" ? "-" : sprintf("%.2fx", c[1] / 1000 / $2);
  if (a[2] + b[2] + c[2] > 0) printf "  limit violations: plain %s, g261 %s, hsc %s\n", a[2], b[2], c[2] }'
rm -rf "$work"
