#!/bin/sh
# KRN-6: XY plot of a contoured corner (docs/contour_corner.png): the
# programmed polyline, the commanded (smoothed) path and the actual
# positions of the drive simulators, zoomed at the first corner of
# scenarios/contour/corner.yaml. Reuses the rig's plot data (plots/xy.tsv of
# `hil run`). Usage: bench/contour_plot.sh [OUT.png]  (run from the worktree)
set -eu
out=${1:-docs/contour_corner.png}
run=$(mktemp -d)
scripts/in_netns.sh build/bin/hil run scenarios/contour/corner.yaml --out "$run/run" >/dev/null
cat > "$run/zoom.gp" <<GP
set terminal pngcairo noenhanced size 1000,900 font ",11"
set output "$out"
set datafile separator "\t"
set grid
set size ratio -1
set key top left
set title "G261, PATH_DEV = 0.05 mm, F3000: the corner at X20 Y0 (N30/N40)"
set xlabel "X [mm]"
set ylabel "Y [mm]"
set xrange [19.8:20.05]
set yrange [-0.05:0.2]
set arrow from 20,0 to 19.9646,0.0354 nohead dt 3 lc rgb "#808080"
set label "0.05 mm" at 19.93,0.06
plot "-" w l lw 3 lc rgb "#a0a0a0" t "programmed", \
     "$run/run/plots/xy.tsv" u 1:2 w l lw 2 lc rgb "#0060c0" t "commanded (contoured)", \
     "" u 3:4 w l lw 1 lc rgb "#d04000" t "actual (drive simulators)"
0	0
20	0
20	20
e
GP
gnuplot "$run/zoom.gp"
echo "$out"
rm -rf "$run"
