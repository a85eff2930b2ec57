#!/usr/bin/env bash
# Scaling benchmark (not a test): the same campaign of 16 LEO runs (scaling.toml) in one process and over two
# MPI ranks; prints the wall times and speed-ups of the whole commands (MPI start-up included) and of
# the campaigns alone (from their own statistics).
#   harness/campaign/bench/scaling.sh [build dir] [stop time s, default the spec's 2400]
# Run it on a quiet machine: every other process on the cores is counted against the ranks.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../../build}
stop=${2:-2400}
cosim=$build/bin/cosim
spec=$here/scaling.toml
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
root=()
[ "$(id -u)" -eq 0 ] && root=(--allow-run-as-root)
args=(campaign "$spec" --fmu-dir "$build/fmus" --runs 16 --stop-time "$stop" --no-figures)

now() { date +%s.%N; }
t0=$(now)
/usr/bin/time -f "%U %S" -o "$work/one.cpu" "$cosim" "${args[@]}" --output "$work/one" > "$work/one.log"
t1=$(now)
OMPI_MCA_btl=self,vader OMPI_MCA_btl_vader_single_copy_mechanism=none \
    /usr/bin/time -f "%U %S" -o "$work/two.cpu" \
    mpirun "${root[@]}" --oversubscribe --bind-to none -n 2 "$cosim" "${args[@]}" --output "$work/two" > "$work/two.log"
t2=$(now)
source "$here/../tests/drop_wall_time.sh"
diff -q <(drop_wall_time "$work/one/results.csv") <(drop_wall_time "$work/two/results.csv") > /dev/null ||
    { echo "the two tables differ"; exit 1; }
echo "1 process : $(head -1 "$work/one.log")"
echo "2 ranks   : $(head -1 "$work/two.log")"
grep "rank " "$work/two.log"
# Whole commands (process and MPI start-up, loading the FMUs on every rank) and the campaigns alone.
inner_one=$(sed -n 's/.* in \([0-9.]*\) s wall.*/\1/p' "$work/one.log")
inner_two=$(sed -n 's/.* in \([0-9.]*\) s wall.*/\1/p' "$work/two.log")
awk -v a="$t0" -v b="$t1" -v c="$t2" -v i1="$inner_one" -v i2="$inner_two" 'BEGIN { one = b - a; two = c - b;
    printf "commands: 1 process %.2f s, 2 ranks %.2f s, speed-up %.2f\n", one, two, one / two;
    printf "campaigns alone: 1 process %.2f s, 2 ranks %.2f s, speed-up %.2f\n", i1, i2, i1 / i2 }'
# CPU time (user + system) of each command with its ranks: equal totals mean the ranks add no work,
# and a speed-up below 2 then comes from the share of the cores the other processes took.
awk '{ printf "CPU: %s %.2f s\n", FILENAME ~ /one/ ? "1 process" : "2 ranks  ", $1 + $2 }' "$work/one.cpu" "$work/two.cpu"
