# The figure of an identify run (analysis identify), titled with its deck's title (read
# from the data file's first line, never written here):
#   a record: the record and the fitted model above, the residuals (measured - model) below
#     (OUT/NAME.fit.dat, one block per release);
#   periods: the timed periods (per cycle, with their u) against amplitude, the model's
#     periods at the estimate and the classical formula's (OUT/NAME.periods.dat).
# usage (from the repository root):
#   gnuplot -c plots/identify.gp                 every output/*.identify -> plots/NAME.identify.png
#   gnuplot -c plots/identify.gp OUT/NAME [PNG]  one run (default PNG plots/NAME.identify.png)
load 'plots/style.gpi'
set terminal pngcairo size 900,640 enhanced font 'DejaVu Sans,12' linewidth 1.5

# first line of a file after its '# bifilar identify ...: ' prefix
title_of(f) = system(sprintf("head -n 1 '%s' | sed 's/^# bifilar identify [a-z]*: //'", f))
file_exists(f) = system(sprintf("[ -f '%s' ] && echo 1 || echo 0", f)) eq "1"

draw_fit(data, png) = sprintf("data = '%s'; png = '%s'; load 'plots/identify_fit.gpi'", data, png)
draw_periods(data, png) = sprintf("data = '%s'; png = '%s'; load 'plots/identify_periods.gpi'", data, png)

if (ARGC >= 1) {
    runs = ARG1
} else {
    runs = system("ls output/*.identify 2>/dev/null | sed 's/[.]identify$//'")
}
do for [run in runs] {
    base = system(sprintf("basename '%s'", run))
    png = (ARGC >= 2) ? ARG2 : sprintf('plots/%s.identify.png', base)
    if (file_exists(run.'.fit.dat')) {
        eval draw_fit(run.'.fit.dat', png)
    } else {
        if (file_exists(run.'.periods.dat')) {
            eval draw_periods(run.'.periods.dat', png)
        }
    }
}
