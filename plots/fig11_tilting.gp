# Fig. 11  Tilting; triangular plate
# usage (from the repository root): gnuplot -c plots/fig11_tilting.gp [DATA] [PNG]
data = (ARGC >= 1) ? ARG1 : 'output/triangle_plate.dat'
png  = (ARGC >= 2) ? ARG2 : 'plots/fig11_tilting.png'
load 'plots/style.gpi'
set output png
set title "Fig. 11  Tilting; triangular plate"
set ylabel "tilting {/Symbol q}_1 (deg)"
plot data using 1:($2*180/pi) with lines ls 1 notitle
