# The inertia tensor from several hangs (analysis tensor): each hang's vertical moment as
# its periods give it, with its standard uncertainty, against the fitted tensor's u . J u
# (above, with the diagonal), and their difference (below).
# usage (from the repository root): gnuplot -c plots/tensor.gp [DATA] [PNG] [TITLE]
# DATA is a NAME.tensor.dat of bifilar; the title is TITLE, else line 1 of DATA.
data  = (ARGC >= 1) ? ARG1 : 'output/tensor_example.tensor.dat'
png   = (ARGC >= 2) ? ARG2 : 'plots/tensor.png'
title = (ARGC >= 3) ? ARG3 : system(sprintf("head -n 1 '%s' | sed -e 's/^# *//'", data))
load 'plots/style.gpi'
set terminal pngcairo size 900,700 enhanced font 'DejaVu Sans,12' linewidth 1.5
set output png
set multiplot
set lmargin 14
set rmargin 3
set size 1, 0.62
set origin 0, 0.38
set title title noenhanced
set xlabel ''
set format x '%g'
set ylabel 'I_v of the hang (mass x length^2)'
set key top left box opaque
set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05
plot x with lines lc rgb '#888888' lw 1 title 'I_v = u . J u', \
     data using 2:3:4 with yerrorbars pt 7 ps 1.0 lc rgb '#1f4e9c' title 'its periods (u)', \
     data using 2:3:(sprintf(' %d', $1)) with labels left offset 0.6,0.4 font ',10' notitle
unset title
set size 1, 0.38
set origin 0, 0
set offsets graph 0.05, graph 0.05, graph 0.1, graph 0.1
set xlabel 'u . J u of the fitted tensor (mass x length^2)'
set ylabel 'I_v - u . J u'
set format y '%.1e'
unset key
plot 0 with lines lc rgb '#888888' lw 1 notitle, \
     data using 2:($3 - $2):4 with yerrorbars pt 7 ps 1.0 lc rgb '#c0392b' notitle
unset multiplot
