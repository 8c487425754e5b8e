# theta1 (tilting) of the Figs. 4-6 cylinder: elastic cables (stiffness 1e6, damping 0.05)
# against the paper's inextensible model
# usage (from the repository root):
#   gnuplot -c plots/elastic_vs_kane.gp [ELASTIC_DAT] [KANE_DAT] [PNG]
el   = (ARGC >= 1) ? ARG1 : 'output/cylinder_l180_elastic.dat'
kane = (ARGC >= 2) ? ARG2 : 'output/cylinder_l180.dat'
png  = (ARGC >= 3) ? ARG3 : 'plots/elastic_vs_kane.png'
load 'plots/style.gpi'
set output png
set title "Tilting {/Symbol q}_1, cylinder l = 2b, l' = 1.8b: elastic cables (EA/mg = 10^6) and the paper's model"
set ylabel "tilting {/Symbol q}_1 (deg)"
set key top right box opaque
plot kane using 1:($2*180/pi) with lines ls 1 title "paper's model (inextensible)", \
     el using 1:($2*180/pi) with lines ls 2 dt 2 title 'elastic cables'
