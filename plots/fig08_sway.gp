# Fig. 8  Side-sway; l = 2b, l' = 1.95b
# usage (from the repository root): gnuplot -c plots/fig08_sway.gp [DATA] [PNG]
data = (ARGC >= 1) ? ARG1 : 'output/cylinder_l195.dat'
png  = (ARGC >= 2) ? ARG2 : 'plots/fig08_sway.png'
load 'plots/style.gpi'
set output png
set title "Fig. 8  Side-sway; l = 2b, l' = 1.95b"
set ylabel "side-sway Q"
plot data using 1:12 with lines ls 1 notitle
