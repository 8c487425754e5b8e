#!/bin/sh
# kill_run.sh FILE WHAT CMD ...: run CMD; as soon as FILE exists, kill it, and wait for it.
#   WHAT = KILL, TERM, INT: that signal to CMD's process;
#   WHAT = rankN: SIGKILL to MPI rank N (CMD is mpirun: the rank is the child of that mpirun
#          whose environment holds OMPI_COMM_WORLD_RANK=N).
# Exit status: CMD's; 200 when CMD ended before FILE appeared (nothing was killed), 124 when
# FILE did not appear within 120 s (CMD is then killed).  Used by tests/test_sweep.f90.
file=$1
what=$2
shift 2
"$@" &
pid=$!
i=0
while [ ! -e "$file" ]; do
    if ! kill -0 "$pid" 2>/dev/null; then
        wait "$pid"
        exit 200
    fi
    i=$((i + 1))
    if [ $i -gt 12000 ]; then
        kill -KILL "$pid"
        wait "$pid"
        exit 124
    fi
    sleep 0.01
done
case $what in
rank*)
    n=${what#rank}
    for c in $(pgrep -P "$pid"); do
        if tr '\0' '\n' < "/proc/$c/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$n"
        then
            kill -KILL "$c"
        fi
    done
    ;;
*)
    kill "-$what" "$pid"
    ;;
esac
wait "$pid"
