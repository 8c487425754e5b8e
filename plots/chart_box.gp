# Stability chart of the parallelepiped hung from its top edges (input/box_chart.nml).
# usage (from the repository root): gnuplot -c plots/chart_box.gp [CHART_DAT] [PNG]
data = (ARGC >= 1) ? ARG1 : 'output/box_chart.chart.dat'
png  = (ARGC >= 2) ? ARG2 : 'plots/chart_box.png'
eval sprintf("call 'plots/heatmap.gpi' '%s' '%s' '%s'", data, png, \
     'Parallelepiped hung from its top edges: stability of pure torsion')
