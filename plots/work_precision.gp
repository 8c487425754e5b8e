# Work-precision: error against CPU time, LSODA (rtol 1e-3 ... 1e-12) and fixed-step RK4
# usage (from the repository root): gnuplot -c plots/work_precision.gp [WP] [RK4] [PNG] [TITLE]
wp   = (ARGC >= 1) ? ARG1 : 'output/work_precision_cylinder.wp.dat'
rk4  = (ARGC >= 2) ? ARG2 : 'output/work_precision_cylinder.wp_rk4.dat'
png  = (ARGC >= 3) ? ARG3 : 'plots/work_precision.png'
ttl  = (ARGC >= 4) ? ARG4 : "Error against CPU time, cylinder l = 2b, l' = 1.8b"
load 'plots/style.gpi'
set output png
set title ttl
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'CPU seconds per solve'
set ylabel 'largest error at the output times'
set key top right box opaque
plot wp  using 2:5 with linespoints ls 1 pt 7 title 'LSODA: angles (rad)', \
     wp  using 2:6 with linespoints ls 1 dt 2 pt 6 title 'LSODA: Q / b''', \
     rk4 using 2:5 with linespoints ls 2 pt 5 title 'RK4 fixed step: angles (rad)', \
     rk4 using 2:6 with linespoints ls 2 dt 2 pt 4 title 'RK4 fixed step: Q / b'''
