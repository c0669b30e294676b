#!/bin/sh
# KRN-9 (docs/HSC.md): path velocity over time on the chord circle of 3,000
# chords of 0.1 mm in CAM's 4 decimals at F6000, G261 against #HSC ON
# [BSPLINE PATH_DEV=0.01 MERGE=1], from contour_bench's CSV (cycle x y z v).
# Usage: bench/hsc_plot.sh [OUT.png]  (run from the worktree)
set -eu
out=${1:-docs/hsc_chord_circle.png}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
build/bin/contour_bench --only circle --chords 3000 --decimals 4 --smoothing g261 --csv "$work/g261.csv" > /dev/null
build/bin/contour_bench --only circle --chords 3000 --decimals 4 --smoothing hsc --csv "$work/hsc.csv" > /dev/null
gnuplot <<GP
set terminal pngcairo noenhanced size 1000,500 font ",11"
set output "$out"
set grid
set key top right
set title "3,000 chords of 0.1 mm on R 15.9 mm, 4 decimals, F6000 (100 mm/s), PATH_DEV 0.01"
set xlabel "time [s]"
set ylabel "path velocity [mm/s]"
set yrange [0:120]
plot "$work/hsc.csv" u (\$1/1000):5 w l lw 2 lc rgb "#0060c0" t "#HSC ON [BSPLINE MERGE=1]: 3.2 s", \
     "$work/g261.csv" u (\$1/1000):5 w l lw 1 lc rgb "#d04000" t "G261 (corner by corner): 23 s"
GP
echo "hsc_plot.sh: $out"
