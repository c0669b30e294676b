#!/bin/sh
# KRN-3: `jerk_cases IN.csv OUT.csv` appends duration and ok to each row;
# the rest-to-rest rows must give the closed-form durations.
set -eu
bin=$1; work=$2
mkdir -p "$work"
cat >"$work/in.csv" <<'CSV'
p0,v0,a0,pf,vf,af,vmax,amax,jmax
0,0,0,0.05,0,0,0.1,1,20
0,0,0,0.01,0,0,0.1,1,20
0,0,0,0.0005,0,0,0.1,1,20
0.003,0.05,0.5,-0.002,0,0,0.1,1,20
0,0,0,0.01,0.1,0,0.1,1,20
0,0,0,0.01,0,0,-1,1,20
CSV
"$bin/jerk_cases" "$work/in.csv" "$work/out.csv"
cat "$work/out.csv"
awk -F, '
  NR == 1 { if ($10 != "duration" || $11 != "ok") { print "bad header"; exit 1 } next }
  function near(x, y) { return (x - y < 1e-12 && y - x < 1e-12) }
  NR == 2 && !(near($10, 0.05/0.1 + 0.1/1 + 1/20) && $11 == 1) { print "row 2"; exit 1 }
  NR == 3 && !(near($10, 2 * ((-0.05 + sqrt(0.0025 + 0.04)) / 2 + 0.05)) && $11 == 1) { print "row 3"; exit 1 }
  NR == 4 && !(near($10, 4 * exp(log(0.0005 / 40) / 3)) && $11 == 1) { print "row 4"; exit 1 }
  NR == 5 && $11 != 1 { print "row 5"; exit 1 }
  NR >= 6 && $11 != 0 { print "row " NR " should not be ok"; exit 1 }
  END { if (NR != 7) { print "rows missing"; exit 1 } }
' "$work/out.csv"
