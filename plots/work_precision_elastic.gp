# Work-precision of the elastic-cable model (input/work_precision_elastic.nml): LSODA with the
# cables' modes and fixed-step RK4 from its stability bound down.
# usage (from the repository root): gnuplot -c plots/work_precision_elastic.gp
call 'plots/work_precision.gp' 'output/work_precision_elastic.wp.dat' \
     'output/work_precision_elastic.wp_rk4.dat' 'plots/work_precision_elastic.png' \
     "Error against CPU time, elastic cables k = 1e6, zeta = 0.5 (cylinder, tau = 0 ... 3)"
