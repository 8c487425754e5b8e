# Fig. 15: Floquet multipliers of pure torsion at 45 degrees, stable suspension.  Each multiplier
# lambda is drawn at its argument (degrees) and modulus (log scale); |lambda| = 1 is the
# stability limit.  The four trivial multipliers (1 by structure) are drawn open.
# usage (from the repository root): gnuplot -c plots/fig15_multipliers_stable.gp [FLOQUET] [PNG]
data = (ARGC >= 1) ? ARG1 : 'output/box_stable.floquet'
png  = (ARGC >= 2) ? ARG2 : 'plots/fig15_multipliers_stable.png'
load 'plots/style.gpi'
set output png
mods = system("awk '/^max_modulus/{print $3}' ".data)
set title sprintf("Fig. 15  Floquet multipliers, stable suspension: largest |{/Symbol l}| = %.4g", real(mods))
set xlabel 'arg {/Symbol l} (deg)'
set ylabel '|{/Symbol l}|'
set logscale y
set xrange [-180:180]
set xtics 45
set yrange [*:*]
set key top left box opaque
rows = "< awk '/^# multipliers/{on=1; next} on' ".data
plot 1 with lines lc rgb '#888888' dt 2 title '|{/Symbol l}| = 1', \
     rows using (atan2($2,$1)*180/pi):(strcol(4) eq 'no' ? $3 : 1/0) with points pt 7 ps 1.8 lc rgb '#c0392b' title 'multipliers', \
     rows using (atan2($2,$1)*180/pi):(strcol(4) eq 'yes' ? $3 : 1/0) with points pt 6 ps 2.2 lc rgb '#1f4e9c' title 'trivial (1 by structure)'
