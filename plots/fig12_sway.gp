# Fig. 12  Side-sway; triangular plate
# usage (from the repository root): gnuplot -c plots/fig12_sway.gp [DATA] [PNG]
data = (ARGC >= 1) ? ARG1 : 'output/triangle_plate.dat'
png  = (ARGC >= 2) ? ARG2 : 'plots/fig12_sway.png'
load 'plots/style.gpi'
set output png
set title "Fig. 12  Side-sway; triangular plate"
set ylabel "side-sway Q"
plot data using 1:12 with lines ls 1 notitle
