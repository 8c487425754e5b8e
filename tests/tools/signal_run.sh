#!/bin/sh
# signal_run.sh SIG WHEN CMD ...: run CMD; send it signal SIG (INT, TERM, HUP, ...) when WHEN
# comes, and wait for it.
#   WHEN = SECONDS (a number, fractions allowed): that long after CMD started;
#   WHEN = file:GLOB: as soon as a file matching the shell pattern GLOB exists (looked for
#          every 2 ms, for at most a minute), e.g. file:out/deck.chart.partial or
#          'file:out/deck.dat.tmp.*';
#   WHEN = rank0:SECONDS or rank0:file:GLOB: the same, but the signal goes to MPI rank 0
#          (CMD is mpirun: the child of that mpirun whose environment holds
#          OMPI_COMM_WORLD_RANK=0).
# When CMD ends first, nothing is sent.  Exit status: CMD's.  Used by
# tests/test_fuzz_resume.f90.
sig=$1
when=$2
shift 2
"$@" &
pid=$!
target=$pid
case $when in
rank0:*)
    target=rank0
    when=${when#rank0:}
    ;;
esac
case $when in
file:*)
    pattern=${when#file:}
    i=0
    found=
    while [ -z "$found" ] && kill -0 "$pid" 2>/dev/null && [ $i -lt 30000 ]; do
        i=$((i + 1))
        for f in $pattern; do
            [ -e "$f" ] && found=1
        done
        [ -z "$found" ] && sleep 0.002
    done
    ;;
*)
    sleep "$when"
    ;;
esac
if [ "$target" = rank0 ]; then
    for c in $(pgrep -P "$pid"); do
        if tr '\0' '\n' < "/proc/$c/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=0"
        then
            kill "-$sig" "$c" 2>/dev/null
        fi
    done
else
    kill "-$sig" "$pid" 2>/dev/null
fi
wait "$pid"
