# Fig. 4  Torsion; l = 2b, l' = 1.8b
# usage (from the repository root): gnuplot -c plots/fig04_torsion.gp [DATA] [PNG]
data = (ARGC >= 1) ? ARG1 : 'output/cylinder_l180.dat'
png  = (ARGC >= 2) ? ARG2 : 'plots/fig04_torsion.png'
load 'plots/style.gpi'
set output png
set title "Fig. 4  Torsion; l = 2b, l' = 1.8b"
set ylabel "torsion {/Symbol q}_4 (deg)"
plot data using 1:($5*180/pi) with lines ls 1 notitle
