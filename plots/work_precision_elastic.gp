# Work-precision of the elastic-cable model (input/work_precision_elastic.nml: k = 1e6,
# zeta = 0.01): Radau IIA (generalized coordinates), LSODA (maximal coordinates), both at
# rtol = 1e-3 ... 1e-12, and fixed-step RK4 from its stability bound down; largest angle
# error at the output times against the reference (Radau rtol 1e-13, confirmed by LSODA and
# by RK4 + Richardson).
# usage (from the repository root):
#   gnuplot -c plots/work_precision_elastic.gp [WP] [RK4] [RADAU] [PNG]
wp    = (ARGC >= 1) ? ARG1 : 'output/work_precision_elastic.wp.dat'
rk4   = (ARGC >= 2) ? ARG2 : 'output/work_precision_elastic.wp_rk4.dat'
rad   = (ARGC >= 3) ? ARG3 : 'output/work_precision_elastic.wp_radau.dat'
png   = (ARGC >= 4) ? ARG4 : 'plots/work_precision_elastic.png'
load 'plots/style.gpi'
set output png
set title "Error against CPU time, elastic cables k = 1e6, {/Symbol z} = 0.01 (cylinder, {/Symbol t} = 0 ... 3)"
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'CPU seconds per solve'
set ylabel 'largest angle error at the output times (rad)'
set key top right box opaque
plot rad using 2:5 with linespoints ls 3 pt 9 title 'Radau IIA, rtol 10^{-3} ... 10^{-12}', \
     wp  using 2:5 with linespoints ls 1 pt 7 title 'LSODA, rtol 10^{-3} ... 10^{-12}', \
     rk4 using 2:5 with linespoints ls 2 pt 5 title 'RK4, fixed step from the stability bound'
