# Fig. 16: stable tilting: theta1 after release from 45 degrees of torsion with theta1 = 0.01 rad.
# usage (from the repository root): gnuplot -c plots/fig16_stable_tilting.gp [DATA] [PNG]
data = (ARGC >= 1) ? ARG1 : 'output/box_stable.dat'
png  = (ARGC >= 2) ? ARG2 : 'plots/fig16_stable_tilting.png'
load 'plots/style.gpi'
set output png
set title "Fig. 16  Stable tilting: parallelepiped, 45{/Symbol \260} torsion, {/Symbol q}_1(0) = 0.01 rad"
set ylabel 'tilting {/Symbol q}_1 (deg)'
plot data using 1:($2*180/pi) with lines ls 1 notitle
