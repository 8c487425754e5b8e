#!/usr/bin/env bash
# MPI figures of make bench (issue 15): strong scaling of the 60 x 45 chart of
# input/box_chart.nml on 1 and 2 ranks of one thread each, with the parallel efficiency;
# rank 0 handing out work only (BIFILAR_RANK0_COMPUTES=no) beside; rank 0's time per
# request for work (sweep_probe_mpi, points that cost nothing); the process start; then
# bench_sweep: the cost of each point on one thread and the model of a 1000 x 1000 chart on
# 2, 64 and 1024 cores.  Usage: tests/bench/mpi_scaling.sh BINDIR OUTFILE [RUNS]
# (BINDIR holds bifilar_mpi, sweep_probe_mpi and bench_sweep).  Wall times are the sweep's
# own (the `chart ... s` of the summary line), the median of RUNS runs (default 5) taken
# in turn, so that a disturbance of the shared machine hits every configuration alike.
set -euo pipefail
bin=${1:-bin}
out=${2:-output/bench_mpi.dat}
runs=${3:-5}
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
# the start: mpirun -np 2 bifilar_mpi --version, whole
t0=$(date +%s.%N)
$mpi -np 2 "$bin/bifilar_mpi" --version >/dev/null
start=$(echo "$t0 $(date +%s.%N)" | awk '{printf "%.2f", $2 - $1}')
echo "start of 2 ranks (mpirun -np 2 bifilar_mpi --version): $start s"

load=$(cut -d' ' -f1-3 /proc/loadavg)
for k in $(seq 1 "$runs"); do
    $mpi -np 1 "$bin/bifilar_mpi" "$deck" --out "$scratch" | sweep_s >> "$scratch/np1.$$"
    $mpi -np 2 "$bin/bifilar_mpi" "$deck" --out "$scratch" | sweep_s >> "$scratch/np2.$$"
    $mpi -np 2 -x BIFILAR_RANK0_COMPUTES=no "$bin/bifilar_mpi" "$deck" --out "$scratch" |
        sweep_s >> "$scratch/np2s.$$"
done
t1=$(median < "$scratch/np1.$$")
t2=$(median < "$scratch/np2.$$")
t2s=$(median < "$scratch/np2s.$$")
{
    echo "# bench_mpi: strong scaling of the 60 x 45 chart $deck, one thread per rank"
    echo "# sweep wall seconds, median of $runs runs; efficiency = T(1) / (ranks T(ranks))"
    echo "# load average before the runs: $load"
    echo "# ranks rank0 seconds efficiency runs..."
    echo "1 computes $t1 1.000 $(tr '\n' ' ' < "$scratch/np1.$$")"
    echo "2 computes $t2 $(echo "$t1 $t2" | awk '{printf "%.3f", $1 / (2 * $2)}') $(tr '\n' ' ' < "$scratch/np2.$$")"
    echo "2 serves $t2s $(echo "$t1 $t2s" | awk '{printf "%.3f", $1 / (2 * $2)}') $(tr '\n' ' ' < "$scratch/np2s.$$")"
} > "$out"
rm -f "$scratch"/np*.$$
echo "strong scaling of $deck (sweep seconds, median of $runs; load average $load; $out):"
awk '!/^#/ {printf "  %s rank(s), rank 0 %-8s %6.2f s  efficiency %s\n", $1, $2, $3, $4}' "$out"
OMP_NUM_THREADS=1 "$bin/bench_sweep" "$deck" output/bench_sweep.dat "$t_req" "$start"
