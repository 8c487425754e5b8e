# Rig design for the parallelepiped of Figs. 13-16 (input/box_design.nml): the largest Floquet
# multiplier against the cable length at six amplitudes up to 50 degrees, the unstable bands
# shaded, the predicted u(I1)/I1 on the right axis, the recommended suspension marked.
# usage (from the repository root): gnuplot -c plots/box_design_design.gp [DESIGN] [PNG]
data = (ARGC >= 1) ? ARG1 : 'output/box_design.design'
png  = (ARGC >= 2) ? ARG2 : 'plots/box_design_design.png'
eval sprintf("call 'plots/design.gpi' '%s' '%s' '' '%s'", data, png, 'm')
