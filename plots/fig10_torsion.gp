# Fig. 10  Torsion; triangular plate
# usage (from the repository root): gnuplot -c plots/fig10_torsion.gp [DATA] [PNG]
data = (ARGC >= 1) ? ARG1 : 'output/triangle_plate.dat'
png  = (ARGC >= 2) ? ARG2 : 'plots/fig10_torsion.png'
load 'plots/style.gpi'
set output png
set title "Fig. 10  Torsion; triangular plate"
set ylabel "torsion {/Symbol q}_4 (deg)"
plot data using 1:($5*180/pi) with lines ls 1 notitle
