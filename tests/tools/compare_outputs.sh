#!/usr/bin/env bash
# Runs every shipped deck (input/, input/extreme/, input/more/, tests/bench/chart_cylinder.nml)
# with a given binary into DIR, then (with a second DIR) compares the two runs file by file:
# the same files, the same exit statuses, the same stderr lines, and the same bytes once
# CPU times are masked (key lines whose key holds "cpu", the cpu_seconds column of the
# work-precision tables, and the "cpu" parts of the summary lines on stdout).
#
#   tests/tools/compare_outputs.sh run BIN DIR       # run the decks with BIN into DIR
#   tests/tools/compare_outputs.sh diff DIR1 DIR2    # compare two runs; exit 1 on a difference
#
# Used to show that a restructuring leaves every output as it was.
set -u
mask() {
    # key = value lines with cpu in the key; wp tables' second column; "cpu 0.0229 s"
    sed -E -e '/^[A-Za-z_]*cpu[A-Za-z_]* *=/d' -e 's/cpu [0-9.eE+-]+ s/cpu X s/g' -e 's/(, |\()[0-9.]+ s(\)|$)/\1X s\2/g' "$1" |
    if [[ "$1" == *.wp*.dat ]]; then
        awk '/^#/ {print; next} {$2 = "X"; print}'
    else cat; fi
}
case "${1:-}" in
run)
    bin=$2; dir=$3
    rm -rf "$dir"; mkdir -p "$dir"
    for d in input/*.nml input/extreme/*.nml input/more/*.nml tests/bench/chart_cylinder.nml; do
        sub=$(basename "$(dirname "$d")")
        "$bin" "$d" --out "$dir/$sub" >>"$dir/stdout.txt" 2>>"$dir/stderr.txt"
        echo "$d $?" >>"$dir/exit.txt"
    done ;;
diff)
    a=$2; b=$3; bad=0
    fa=$(cd "$a" && find . -type f | sort); fb=$(cd "$b" && find . -type f | sort)
    if [ "$fa" != "$fb" ]; then echo "different files:"; diff <(echo "$fa") <(echo "$fb"); bad=1; fi
    for f in $fa; do
        [ -f "$b/$f" ] || continue
        if ! cmp -s <(mask "$a/$f") <(mask "$b/$f"); then
            echo "differs: $f"; diff <(mask "$a/$f") <(mask "$b/$f") | head -6; bad=1
        fi
    done
    [ $bad = 0 ] && echo "identical: $(echo "$fa" | wc -l) files (CPU times masked)"
    exit $bad ;;
*) sed -n '2,11p' "$0"; exit 2 ;;
esac
