#!/usr/bin/env bash
# MPI figures of make bench: strong scaling of the 60 x 45 chart of
# input/box_chart.nml on 1 and 2 ranks of one thread each, with the parallel efficiency;
# rank 0 handing out work only (BIFILAR_RANK0_COMPUTES=no) beside; rank 0's time per
# request for work (sweep_probe_mpi, points that cost nothing); the process start; the
# same strong scaling of identify's Monte Carlo (on the sweep engine): 2000 samples from
# the periods of input/identify_periods.nml (RUNS runs) and 200 refits of the gyro record of
# input/more/identify_record_mc.nml (3 runs), into OUTFILE with _mc_periods and _mc_record
# before .dat; then bench_sweep: the cost of each chart point on one thread and the model of
# a 1000 x 1000 chart on 2, 64 and 1024 cores.
# Usage: tests/bench/mpi_scaling.sh BINDIR OUTFILE [RUNS]
# (BINDIR holds bifilar_mpi, sweep_probe_mpi and bench_sweep).  Wall times are the sweep's
# own (the `chart ... s` of the summary line, the Monte Carlo's `from N samples, ... s`),
# the median and the least of RUNS runs (default 7) taken in turn, so that a disturbance of
# the shared machine hits every configuration alike; bin/bifilar with 1 and 2 OpenMP
# threads beside.
set -euo pipefail
bin=${1:-bin}
out=${2:-output/bench_mpi.dat}
runs=${3:-7}
deck=input/box_chart.nml
scratch=build/bench/mpi
mkdir -p "$scratch" "$(dirname "$out")"
if ! command -v mpirun >/dev/null 2>&1 || [ ! -x "$bin/bifilar_mpi" ]; then
    echo "mpi_scaling.sh: no OpenMPI or no $bin/bifilar_mpi (make mpi); no MPI figures" >&2
    exit 0
fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
mpi="mpirun -q --oversubscribe -x OMP_NUM_THREADS=1"
# the sweep's seconds from a summary line: '... chart 2700 points, 2052 stable, 2.67 s ...'
sweep_s() { sed -n 's/.* stable, \([0-9.]*\) s.*/\1/p'; }
median() { sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }

# rank 0's time per request: 200 000 points that cost nothing, 2 ranks
probe=$($mpi -np 2 "$bin/sweep_probe_mpi" ok 200000 "$deck" "" 0)
# its line: ok N BAD RANK0_POINTS OTHER_POINTS WALL_S REQUESTS SERVE_S
t_req=$(echo "$probe" | awk '{printf "%.2f", 1e6 * $8 / $7}')
echo "rank 0 per request (sweep_probe_mpi, 200000 points of no cost, 2 ranks): $t_req us" \
     "($(echo "$probe" | awk '{print $7}') requests, $(echo "$probe" | awk '{print $8}') s" \
     "of $(echo "$probe" | awk '{print $6}') s)"
probe1=$($mpi -np 1 "$bin/sweep_probe_mpi" ok 200000 "$deck" "" 0)
echo "the engine's own cost (sweep_probe_mpi, 200000 points of no cost, 1 rank):" \
     "$(echo "$probe1" | awk '{printf "%.2f us a point (%s s)", 1e6 * $6 / $2, $6}')"
# the start: mpirun -np 2 bifilar_mpi --version, whole
t0=$(date +%s.%N)
$mpi -np 2 "$bin/bifilar_mpi" --version >/dev/null
start=$(echo "$t0 $(date +%s.%N)" | awk '{printf "%.2f", $2 - $1}')
echo "start of 2 ranks (mpirun -np 2 bifilar_mpi --version): $start s"

# run CONFIG DECK: one run of a configuration
run() {
    case $1 in
    np1) $mpi -np 1 "$bin/bifilar_mpi" "$2" --out "$scratch" ;;
    np2) $mpi -np 2 "$bin/bifilar_mpi" "$2" --out "$scratch" ;;
    np2s) $mpi -np 2 -x BIFILAR_RANK0_COMPUTES=no "$bin/bifilar_mpi" "$2" --out "$scratch" ;;
    ser1) OMP_NUM_THREADS=1 "$bin/bifilar" "$2" --out "$scratch" ;;
    ser2) OMP_NUM_THREADS=2 "$bin/bifilar" "$2" --out "$scratch" ;;
    esac
}
eff() { echo "$1 $2 $3" | awk '{printf "%.3f", $1 / ($3 * $2)}'; }
# measure DECK EXTRACT RUNS TITLE OUTFILE CONFIG...: RUNS runs of each configuration, in
# turn, each round starting one further (a slow spell of the shared machine then hits each
# configuration alike); EXTRACT takes the sweep's seconds from the summary line; the table
# (median, least, efficiency against np1) into OUTFILE and on stdout
measure() {
    local deck=$1 extract=$2 n=$3 title=$4 file=$5
    shift 5
    local names=("$@") k j c p m l load
    load=$(cut -d' ' -f1-3 /proc/loadavg)
    for k in $(seq 0 $((n - 1))); do
        for j in $(seq 0 $((${#names[@]} - 1))); do
            c=${names[$(( (j + k) % ${#names[@]} ))]}
            run "$c" "$deck" | $extract >> "$scratch/$c.$$"
        done
    done
    for c in "${names[@]}"; do
        eval "med_$c=$(median < "$scratch/$c.$$")"
        eval "min_$c=$(sort -g "$scratch/$c.$$" | head -1)"
    done
    {
        echo "# bench_mpi: strong scaling of $title, $deck"
        echo "# sweep wall seconds (the summary line's), median and least of $n runs taken in turn;"
        echo "# efficiency = T(1 rank) / (cores T(cores)), from the medians and from the least"
        echo "# load average before the runs: $load"
        echo "# config cores median least eff_median eff_least runs..."
        for c in "${names[@]}"; do
            case $c in np1|ser1) p=1 ;; *) p=2 ;; esac
            eval "m=\$med_$c; l=\$min_$c"
            echo "$c $p $m $l $(eff "$med_np1" "$m" $p) $(eff "$min_np1" "$l" $p) $(tr '\n' ' ' < "$scratch/$c.$$")"
        done
    } > "$file"
    rm -f "$scratch"/*.$$
    echo "strong scaling of $title, $deck (sweep seconds of $n runs; load average $load; $file):"
    echo "  np1: mpirun -np 1, np2: -np 2, np2s: -np 2 with rank 0 only handing out work,"
    echo "  ser1, ser2: bin/bifilar with 1 and 2 OpenMP threads; efficiency against np1"
    awk '!/^#/ {printf "  %-5s %d core(s): median %5.2f s, least %5.2f s, efficiency %s (median), %s (least)\n", $1, $2, $3, $4, $5, $6}' "$file"
}
measure "$deck" sweep_s "$runs" "the 60 x 45 chart" "$out" np1 np2 np2s ser1 ser2
# identify's Monte Carlo: '... (Monte Carlo 9.84E-05 from 2000 samples, 0.47 s ...'
mc_s() { sed -n 's/.* samples, \([0-9.]*\) s.*/\1/p'; }
measure input/identify_periods.nml mc_s "$runs" "the Monte Carlo of 2000 periods samples" \
    "${out%.dat}_mc_periods.dat" np1 np2 ser1 ser2
measure input/more/identify_record_mc.nml mc_s 3 "the Monte Carlo of 200 record samples" \
    "${out%.dat}_mc_record.dat" np1 np2 ser1 ser2
OMP_NUM_THREADS=1 "$bin/bench_sweep" "$deck" output/bench_sweep.dat "$t_req" "$start"
