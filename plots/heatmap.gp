# Stability chart: log10 of the largest Floquet multiplier over two deck parameters, with the
# stable region (largest |lambda| = 1) outlined.  Points where pure torsion is impossible
# (max_modulus < 0 in the data) are left blank.
# usage (from the repository root): gnuplot -c plots/heatmap.gp CHART_DAT PNG [TITLE]
data = ARG1
png = ARG2
ttl = (ARGC >= 3) ? ARG3 : 'Stability of pure torsion'
xname = system("awk '/^# x = /{sub(/,$/,\"\",$4); print $4; exit}' ".data)
yname = system("awk '/^# x = /{print $7; exit}' ".data)
label(n) = n eq 'l' ? "cable length l / b'" : n eq 'b' ? "b / b'" : \
           n eq 'amplitude' ? 'torsion amplitude (deg)' : n eq 'r' ? "r / b'" : \
           n eq 'lambda' ? '{/Symbol l} (rad)' : 'I_3 / I_1'
load 'plots/style.gp'
set terminal pngcairo size 900,700 enhanced font 'DejaVu Sans,12'
set output png
# the stable boundary: contour of log10(max modulus) just above 0
set table $contour
set contour base
set cntrparam levels discrete 1e-4
unset surface
set view map
splot data using 1:2:($3 > 0 ? log10($3) : 1/0) with lines notitle
unset table
unset contour
set title ttl
set xlabel label(xname)
set ylabel label(yname)
set cblabel 'log_{10} of the largest |{/Symbol l}|'
set palette defined (0 '#f7fbff', 0.02 '#c6dbef', 0.3 '#fdd49e', 1 '#b30000')
set cbrange [0:*]
set key bottom right box opaque
set autoscale fix
plot data using 1:2:($3 > 0 ? log10($3) : 1/0) with image notitle, \
     $contour using 1:2 with lines lw 2.5 lc rgb '#08306b' title 'stable region boundary (|{/Symbol l}| = 1)'
