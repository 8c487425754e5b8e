# The record fit of input/identify_record.nml (analysis identify): the gyro record W and
# the fitted model above, the residuals (measured - model) below.
# usage (from the repository root): gnuplot -c plots/identify_record_fit.gp [DATA] [PNG]
data = (ARGC >= 1) ? ARG1 : 'output/identify_record.fit.dat'
png  = (ARGC >= 2) ? ARG2 : 'plots/identify_record_fit.png'
load 'plots/style.gpi'
set terminal pngcairo size 900,640 enhanced font 'DejaVu Sans,12' linewidth 1.5
set output png
set multiplot
set lmargin 12
set rmargin 3
set size 1, 0.64
set origin 0, 0.36
set title "I1 from a gyro record: laboratory rig, unequal cables, offset mass centre"
set xlabel ''
set format x ''
set ylabel 'W = {/Symbol w} . n_3 (rad/s)'
set key top right box opaque
plot data using 1:3 with lines lc rgb '#1f4e9c' lw 2.5 title 'fitted model', \
     data using 1:2 with points pt 7 ps 0.2 lc rgb '#e67e22' title 'record (gyro, 100 Hz)'
unset title
set size 1, 0.36
set origin 0, 0
set format x '%g'
set xlabel 't (s from release)'
set ylabel 'residual (rad/s)'
unset key
plot data using 1:4 with points pt 7 ps 0.2 lc rgb '#c0392b' notitle, \
     0 with lines lc rgb '#333333' lw 1 notitle
unset multiplot
