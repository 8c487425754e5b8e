#!/usr/bin/env bash
# Speed figures of make bench: instructions (valgrind --tool=callgrind, exact and repeatable)
# and CPU time of one right-hand side, one Floquet analysis (the four Floquet decks of input/
# and the box P3 of tests/bench/box_p3.nml, also as a whole process), one chart point, the start of
# the process, the whole cylinder_l180 deck, the 60 x 6 rig design (input/box_design.nml,
# one thread), identify's units and the multifilar platform's (a right-hand side, an
# LSODA step beside the paper model's, a Radau step of elastic cables).  Usage:
# tests/bench/speed.sh BINDIR OUTFILE (BINDIR holds bifilar, bench_speed, bench_identify,
# bench_platform).  One unit's instructions are the
# difference of a run with N units and one with 0, over N; its CPU time is from a run with
# more units.
set -euo pipefail
bin=${1:-bin}
out=${2:-output/bench_speed.dat}
scratch=build/bench
mkdir -p "$scratch" "$(dirname "$out")"
if ! command -v valgrind >/dev/null 2>&1; then
    echo "speed.sh: valgrind is not installed; no instruction counts" >&2
    exit 0
fi
# instructions of one command
cg() {
    valgrind --tool=callgrind --callgrind-out-file=/dev/null "$@" 2>&1 >/dev/null |
        sed -n 's/.*Collected : *//p'
}
# instructions of one unit: (I(N) - I(0)) / N
per_unit() {
    n=$1; shift
    i0=$(cg "$@" 0)
    i1=$(cg "$@" "$n")
    echo $(( (i1 - i0) / n ))
}
# CPU seconds of one unit (bench_speed prints it, third field)
cpu_unit() {
    "$@" | awk '{print $3}'
}
# CPU seconds of one process, from REPS runs (user + system of the children: the shell's
# fork of each is counted too; process_true shows that floor)
cpu_process() {
    local reps=$1 t
    shift
    TIMEFORMAT='%3U %3S'
    t=$( { time (for ((i = 0; i < reps; i++)); do "$@" >/dev/null 2>&1 || true; done); } 2>&1 )
    awk -v t="$t" -v r="$reps" 'BEGIN {split(t, a, " "); printf "%.3e", (a[1] + a[2]) / r}'
}
{
    echo "# bifilar speed figures (make bench): what instructions cpu_seconds"
    echo "rhs $(per_unit 2000 "$bin/bench_speed" rhs) $(cpu_unit "$bin/bench_speed" rhs 200000)"
    # the monodromy as the orbit's forward sensitivities (the default), and as the
    # variational equations integrated with the orbit (sensitivities = 'differences')
    for deck in cylinder_torsion box_stable box_unstable box_tall_floquet; do
        echo "floquet_$deck $(per_unit 1 "$bin/bench_speed" floquet $deck) \
$(cpu_unit "$bin/bench_speed" floquet $deck 20)"
        echo "floquet_${deck}_differences $(per_unit 1 "$bin/bench_speed" floquet_differences $deck) \
$(cpu_unit "$bin/bench_speed" floquet_differences $deck 20)"
    done
    # the paper's box P3 (tests/bench/box_p3.nml: the 4 b' block hung at mid-height on
    # cables l = l' = b'/2, 45 degrees, rtol 1e-10): one analysis, and the deck's whole process
    echo "floquet_box_p3 $(per_unit 1 "$bin/bench_speed" floquet tests/bench/box_p3.nml) \
$(cpu_unit "$bin/bench_speed" floquet tests/bench/box_p3.nml 20)"
    echo "floquet_box_p3_process $(cg "$bin/bifilar" tests/bench/box_p3.nml --out "$scratch") \
$(cpu_process 40 "$bin/bifilar" tests/bench/box_p3.nml --out "$scratch")"
    echo "chart_point $(( $(per_unit 1 "$bin/bench_speed" chart) / 30 )) $(cpu_unit "$bin/bench_speed" chart 4)"
    echo "chart_point_differences $(( $(per_unit 1 "$bin/bench_speed" chart_differences) / 30 )) \
$(cpu_unit "$bin/bench_speed" chart_differences 4)"
    echo "process_start $(cg "$bin/bifilar") $(cpu_process 200 "$bin/bifilar")"
    # the floor of cpu_process: any process started from this shell (the fork included)
    echo "process_true $(cg /bin/true) $(cpu_process 200 /bin/true)"
    echo "cylinder_l180 $(cg "$bin/bifilar" input/cylinder_l180.nml --out "$scratch") \
$(cpu_process 40 "$bin/bifilar" input/cylinder_l180.nml --out "$scratch")"
    # the 60 x 6 rig design of the parallelepiped, whole process on one thread
    echo "design_box_60x6 $(OMP_NUM_THREADS=1 cg "$bin/bifilar" input/box_design.nml --out \
"$scratch") $(OMP_NUM_THREADS=1 cpu_process 3 "$bin/bifilar" input/box_design.nml --out "$scratch")"
    # identify: a period inversion; the 30 s, 100 Hz record with three
    # parameters; 2000 Monte Carlo samples from periods (one thread for the count)
    echo "identify_periods $(per_unit 20 "$bin/bench_identify" periods) \
$(cpu_unit "$bin/bench_identify" periods 200)"
    echo "identify_periods_asym $(per_unit 2 "$bin/bench_identify" periods_asym) \
$(cpu_unit "$bin/bench_identify" periods_asym 10)"
    echo "identify_record_3par $(per_unit 1 "$bin/bench_identify" record) \
$(cpu_unit "$bin/bench_identify" record 3)"
    echo "identify_record_rates_6par $(per_unit 1 "$bin/bench_identify" rates) \
$(cpu_unit "$bin/bench_identify" rates 3)"
    echo "identify_record_3par_differences $(per_unit 1 "$bin/bench_identify" record_differences) \
$(cpu_unit "$bin/bench_identify" record_differences 3)"
    # tensor: the CubeSat's 9 hangs (27 timings at 10-15 degrees, directions 1-3 degrees
    # off) with 2000 Monte Carlo samples, whole process on one thread
    echo "tensor_cubesat_mc_2000 $(OMP_NUM_THREADS=1 cg "$bin/bifilar" tests/bench/cubesat.nml \
--out "$scratch") $(OMP_NUM_THREADS=1 cpu_process 1 "$bin/bifilar" tests/bench/cubesat.nml --out "$scratch")"
    echo "identify_mc_2000 $(( $(OMP_NUM_THREADS=1 per_unit 200 "$bin/bench_identify" mc) * 2000 )) \
$(OMP_NUM_THREADS=1 cpu_unit "$bin/bench_identify" mc 2000 | awk '{printf "%.5e", $1 * 2000}')"
    # the multifilar platform (bench_platform): a right-hand side of the trifilar, an LSODA
    # step of it at 45 degrees beside one of the paper's model on cylinder_l180 (rtol 1e-10
    # both), a Radau step of the quadrifilar with elastic cables (k = 1e6)
    echo "platform_rhs $(per_unit 2000 "$bin/bench_platform" rhs) \
$(cpu_unit "$bin/bench_platform" rhs 200000)"
    echo "bifilar_step $(per_unit 500 "$bin/bench_platform" bifilar_step) \
$(cpu_unit "$bin/bench_platform" bifilar_step 20000)"
    echo "platform_step $(per_unit 500 "$bin/bench_platform" step) \
$(cpu_unit "$bin/bench_platform" step 20000)"
    echo "platform_elastic_step $(per_unit 200 "$bin/bench_platform" elastic_step) \
$(cpu_unit "$bin/bench_platform" elastic_step 2000)"
    # one point of the trifilar's chart (tests/bench/chart_platform.nml's region and rtol):
    # the instructions of a 4 x 4 chart less a 2 x 2 one, over 12, one thread
    for k in 2 4; do
        sed "s/nx = 100/nx = $k/; s/ny = 100/ny = $k/" tests/bench/chart_platform.nml \
            > "$scratch/chart_platform_$k.nml"
    done
    i2=$(OMP_NUM_THREADS=1 cg "$bin/bifilar" "$scratch/chart_platform_2.nml" --out "$scratch")
    i4=$(OMP_NUM_THREADS=1 cg "$bin/bifilar" "$scratch/chart_platform_4.nml" --out "$scratch")
    echo "platform_chart_point $(( (i4 - i2) / 12 )) 0"
} > "$out.tmp"
mv "$out.tmp" "$out"
awk 'NR == 1 {next} {printf "%-28s %14.0f instructions %12.3e s cpu\n", $1, $2, $3}' "$out"
