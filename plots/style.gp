# Shared look of bifilar's figures: loaded by every plots/*.gp script.
set terminal pngcairo size 900,520 enhanced font 'DejaVu Sans,12' linewidth 1.5
set border lw 1.2
set grid lc rgb '#dddddd' lw 1
set key top right box opaque
unset key   # scripts with several curves set their own key
set xlabel '{/Symbol t} = (g/b'')^{1/2} t'
set style line 1 lc rgb '#1f4e9c' lw 2
set style line 2 lc rgb '#c0392b' lw 2
set style line 3 lc rgb '#2e8b57' lw 2
