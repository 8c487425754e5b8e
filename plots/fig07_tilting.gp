# Fig. 7  Tilting; l = 2b, l' = 1.95b
# usage (from the repository root): gnuplot -c plots/fig07_tilting.gp [DATA] [PNG]
data = (ARGC >= 1) ? ARG1 : 'output/cylinder_l195.dat'
png  = (ARGC >= 2) ? ARG2 : 'plots/fig07_tilting.png'
load 'plots/style.gpi'
set output png
set title "Fig. 7  Tilting; l = 2b, l' = 1.95b"
set ylabel "tilting {/Symbol q}_1 (deg)"
plot data using 1:($2*180/pi) with lines ls 1 notitle
