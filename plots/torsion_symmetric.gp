# Pure torsion of the symmetric cylinder on equal cables: theta4 (torsion) and theta2 (the
# cable's angle from the vertical, through zero twice a period) against tau.
# usage (from the repository root): gnuplot -c plots/torsion_symmetric.gp [DATA] [PNG]
data = (ARGC >= 1) ? ARG1 : 'output/cylinder_torsion.dat'
png  = (ARGC >= 2) ? ARG2 : 'plots/torsion_symmetric.png'
load 'plots/style.gpi'
set output png
set title "Pure torsion; l = l' = 2b (equal cables, symmetric cylinder)"
set ylabel 'angle (deg)'
set key top right box opaque
plot data using 1:($5*180/pi) with lines ls 1 title '{/Symbol q}_4 torsion', \
     data using 1:($3*180/pi) with lines ls 2 title '{/Symbol q}_2 cable BC from vertical', \
     data using 1:($2*180/pi) with lines ls 3 title '{/Symbol q}_1 tilting'
