#!/usr/bin/env bash
# How often rank 0 gets to print its line when another rank dies (README, "Stopping,
# failures and what mpirun prints"): RUNS times, the chart of the test `mpi kill` on 3 ranks,
# rank 1 killed with SIGKILL at the first checkpoint (tests/tools/kill_run.sh), on two cores
# (taskset -c 0,1) shared with BUSY busy-looping processes, with mpirun's
# odls_base_sigkill_timeout = TIMEOUT seconds.  Of the runs where the kill happened (mpirun's
# exit status 137 or 143), prints how many ended with exactly rank 0's one line on stderr
# and how many with none; runs where it did not (the chart ended first, or a time-out) are
# counted apart.
# Usage: tests/bench/kill_window.sh [RUNS [TIMEOUT [BUSY]]]   (defaults 30, 1, 4; bin/bifilar_mpi)
set -euo pipefail
cd "$(dirname "$0")/../.."
runs=${1:-30}
timeout_s=${2:-1}
busy=${3:-4}
if ! command -v mpirun >/dev/null 2>&1 || [ ! -x bin/bifilar_mpi ]; then
    echo "kill_window.sh: no OpenMPI or no bin/bifilar_mpi (make mpi)" >&2
    exit 2
fi
d=build/bench/kill_window
rm -rf "$d"
mkdir -p "$d"
cat > "$d/big.nml" <<'EOF'
&scene title = 'sweep test chart', analyses = 'chart' /
&suspension b = 1.0, b_prime = 1.0, l = 2.0, l_prime = 2.0, g = 1.0 /
&body mass = 1.0, inertia = 0.08854166666666667, 1.416666666666667, 1.338541666666667,
      r = 2.06155281280883, lambda = 1.325817663668033, sway_depth = 4 /
&floquet amplitude = 45.0, segments = 1, rtol = 1e-6 /
&chart x = 'l', x_min = 0.5, x_max = 8.0, nx = 24, y = 'amplitude', y_min = 2.0,
       y_max = 90.0, ny = 16 /
EOF
pids=()
for ((k = 0; k < busy; k++)); do
    taskset -c 0,1 sh -c 'while :; do :; done' &
    pids+=($!)
done
trap 'kill "${pids[@]}" 2>/dev/null || true' EXIT
one=0
none=0
killed=0
for ((i = 1; i <= runs; i++)); do
    rm -rf "$d/big"
    ex=0
    env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1 \
        OMPI_MCA_odls_base_sigkill_timeout="$timeout_s" taskset -c 0,1 timeout 120 \
        tests/tools/kill_run.sh "$d/big/big.chart.partial" rank1 mpirun -q --oversubscribe -np 3 \
        bin/bifilar_mpi "$d/big.nml" --out "$d/big" --checkpoint 0 >/dev/null \
        2>"$d/stderr" || ex=$?
    if [ "$ex" -ne 137 ] && [ "$ex" -ne 143 ]; then
        continue
    fi
    killed=$((killed + 1))
    n=$(wc -l < "$d/stderr")
    if [ "$n" -eq 1 ] && grep -q '^bifilar: error (interrupted): .*stopped by signal 15' \
        "$d/stderr"; then
        one=$((one + 1))
    elif [ "$n" -eq 0 ]; then
        none=$((none + 1))
    fi
done
echo "odls_base_sigkill_timeout = $timeout_s s, $busy busy processes on 2 cores: of $runs" \
    "runs $killed killed a rank; rank 0's line in $one of them, no line in $none"
