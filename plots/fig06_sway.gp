# Fig. 6  Side-sway; l = 2b, l' = 1.8b
# usage (from the repository root): gnuplot -c plots/fig06_sway.gp [DATA] [PNG]
data = (ARGC >= 1) ? ARG1 : 'output/cylinder_l180.dat'
png  = (ARGC >= 2) ? ARG2 : 'plots/fig06_sway.png'
load 'plots/style.gpi'
set output png
set title "Fig. 6  Side-sway; l = 2b, l' = 1.8b"
set ylabel "side-sway Q"
plot data using 1:12 with lines ls 1 notitle
