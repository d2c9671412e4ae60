# SPDX-License-Identifier: MIT
# plot.gp -- log-log plot of error (RMSE against the reference) vs render time, one panel per
# scene, with the Pareto front; reads the CSV written by speed_error.
#   gnuplot -e "csv='docs/speed_error.csv'; out='docs/speed_error.png'; scenes='gears mount bunny'; tscenes='sphere-tess surface-tess'" plot.gp
# tscenes: a second row with the tessellation rows of tess_error (N x N quads, flat and
# interpolated normals, error against time as N grows).
if (!exists("csv")) csv = 'speed_error.csv'
if (!exists("out")) out = 'speed_error.png'
if (!exists("scenes")) scenes = 'gears mount bunny'
if (!exists("tscenes")) tscenes = ''
nt = words(tscenes)
rows = nt > 0 ? 2 : 1
set datafile separator comma
set terminal pngcairo size 1650,600*rows font ",10"
set output out
set logscale xy
set grid
set key top right box opaque font ",9"
# the exact front of scene s, sorted by time (awk + sort: gnuplot breaks lines at filtered rows)
tess(s, k) = sprintf("< awk -F, -v s=%s '$1 == s && $20 ~ /%s$/ { print $10 \",\" $13 \",\" $20 }' '%s'", s, k, csv)
front(s) = sprintf("< awk -F, -v s=%s '$1 == s && $21 == 1 { print $10 \",\" $13 }' '%s' | sort -t, -g", s, csv)
n = words(scenes)
set bmargin 5
set label 1 "labels: 4s, 16s = stratified samples per pixel; 1j, 4j, 16j = jittered; dN = max depth N; c.01 = adaptive cut-off 0.01; gN = grid factor N; corner = SPD corner rays (pixel = mean of its 4 corners); schlick = Schlick Fresnel" at screen 0.5, 0.02 center font ",9"
set multiplot layout rows,n title "gksrt: speed against error (1 thread; RMSE vs 16x16-spp reference; front: settings nobody beats in both)"
do for [i=1:n] {
    s = word(scenes, i)
    set title s
    set xlabel "render time (s, CPU, best of 5 rounds)"
    set ylabel "RMSE (linear RGB clamped to [0,1])"
    plot csv using (strcol(1) eq s ? $10 : 1/0):13 with points pt 6 ps 1 lc rgb "#888888" title "all settings", \
         front(s) using 1:2 with lines lw 2 lc rgb "#1f77b4" title "exact Pareto front", \
         csv using (strcol(1) eq s && $18 == 1 ? $10 : 1/0):13 with points pt 7 ps 1.2 lc rgb "#1f77b4" title "front within noise (time 5 %, RMSE 1 %)", \
         csv using (strcol(1) eq s && $18 == 1 ? $10 : 1/0):13:(strcol(20)) with labels font ",8" offset 0.6,0.4 left tc rgb "#1f77b4" notitle, \
         csv using (strcol(1) eq s && $19 == 1 ? $10 : 1/0):13 with points pt 5 ps 2 lc rgb "#d62728" title "defaults"
}
unset label 1
do for [i=1:nt] {
    s = word(tscenes, i)
    set title s." (N x N quads: Nf flat, Ni interpolated normals)"
    set xlabel "commit + render time (s, CPU, best of 5)"
    set ylabel "RMSE against the very fine / exact surface"
    set format y "%g"
    plot tess(s, "f") using 1:2 with linespoints pt 6 lw 2 lc rgb "#d62728" title "flat", \
         tess(s, "f") using 1:2:3 with labels font ",8" offset 0.6,-0.6 left tc rgb "#d62728" notitle, \
         tess(s, "i") using 1:2 with linespoints pt 7 lw 2 lc rgb "#2ca02c" title "interpolated normals", \
         tess(s, "i") using 1:2:3 with labels font ",8" offset 0.6,0.6 left tc rgb "#2ca02c" notitle
}
unset multiplot
