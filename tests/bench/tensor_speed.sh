#!/usr/bin/env bash
# Speed figures of analysis tensor (make bench): the example deck input/tensor_example.nml
# (9 hangs, 11 timings, exact periods; 8 of the timings at 3 to 20 degrees, so their
# periods are the full model's) without its Monte Carlo, as a whole process: instructions
# (valgrind --tool=callgrind) and CPU seconds (median of 5 runs, one thread); its 2000
# Monte Carlo samples: instructions (the difference of runs with 20 samples and none, times
# 100, one thread) and the wall time of the sweep on 2 threads (the summary line's).
# Usage: tests/bench/tensor_speed.sh BINDIR OUTFILE.  Aims: under 1 s and under 30 s.
set -euo pipefail
bin=${1:-bin}
out=${2:-output/bench_tensor.dat}
scratch=build/bench/tensor
mkdir -p "$scratch" "$(dirname "$out")"
cp input/tensor_example_hangs.csv "$scratch/"
for n in 0 20 2000; do
    sed -e "s/monte_carlo = 2000/monte_carlo = $n/" input/tensor_example.nml > "$scratch/mc$n.nml"
done
# CPU seconds of one process: the median of 5 runs (user + system of the shell's child)
cpu_median() {
    local t
    TIMEFORMAT='%3U %3S'
    for i in 1 2 3 4 5; do
        t=$( { time "$@" >/dev/null 2>&1; } 2>&1 )
        awk -v t="$t" 'BEGIN {split(t, a, " "); print a[1] + a[2]}'
    done | sort -g | sed -n 3p
}
cg() {
    valgrind --tool=callgrind --callgrind-out-file=/dev/null "$@" 2>&1 >/dev/null |
        sed -n 's/.*Collected : *//p'
}
{
    echo "# bifilar tensor speed figures (make bench): what instructions seconds"
    if command -v valgrind >/dev/null 2>&1; then
        i0=$(OMP_NUM_THREADS=1 cg "$bin/bifilar" "$scratch/mc0.nml" --out "$scratch")
        i20=$(OMP_NUM_THREADS=1 cg "$bin/bifilar" "$scratch/mc20.nml" --out "$scratch")
    else
        echo "tensor_speed.sh: valgrind is not installed; no instruction counts" >&2
        i0=0
        i20=0
    fi
    echo "tensor_9_hangs_process_cpu $i0 $(OMP_NUM_THREADS=1 cpu_median "$bin/bifilar" \
"$scratch/mc0.nml" --out "$scratch")"
    wall=$(OMP_NUM_THREADS=2 "$bin/bifilar" "$scratch/mc2000.nml" --out "$scratch" |
           sed -n 's/.* from 2000 samples, \([0-9.]*\) s.*/\1/p')
    echo "tensor_mc_2000_wall_2_threads $(( (i20 - i0) * 100 )) $wall"
} > "$out.tmp"
mv "$out.tmp" "$out"
awk 'NR == 1 {next} {printf "%-32s %14.0f instructions %10.3f s\n", $1, $2, $3}' "$out"
