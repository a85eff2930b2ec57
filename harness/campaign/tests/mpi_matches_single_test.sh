#!/usr/bin/env bash
# The same campaign in one process and over two MPI ranks (loopback, oversubscribed, as root where CI
# runs as root) must give the same results table, wall times aside.
set -euo pipefail
cosim=$1 spec=$2 fmu_dir=$3 work=$4 mpirun=$5
source "$(dirname "$0")/drop_wall_time.sh"
rm -rf "$work"
mkdir -p "$work"
"$cosim" campaign "$spec" --fmu-dir "$fmu_dir" --runs 6 --stop-time 20 --output "$work/single" --no-figures
root=()
[ "$(id -u)" -eq 0 ] && root=(--allow-run-as-root)
# Open MPI 4.1 leaves its own allocations (and those of the components it unloads) to the end of the
# process, which LeakSanitizer reports in a sanitizer build: leak checking is off for the MPI ranks
# only. The same campaign code runs with leak checking in the single-process run above and in
# campaign_tests.
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" \
OMPI_MCA_btl=self,vader OMPI_MCA_btl_vader_single_copy_mechanism=none \
    "$mpirun" "${root[@]}" --oversubscribe --bind-to none -n 2 \
    "$cosim" campaign "$spec" --fmu-dir "$fmu_dir" --runs 6 --stop-time 20 --output "$work/mpi" --no-figures \
    | tee "$work/mpi.log"
grep -q "on 2 ranks" "$work/mpi.log" || { echo "the MPI campaign did not run on 2 ranks"; exit 1; }
diff <(drop_wall_time "$work/single/results.csv") <(drop_wall_time "$work/mpi/results.csv")
[ "$(wc -l < "$work/single/results.csv")" -eq 7 ] || { echo "expected 6 rows"; exit 1; }
echo "identical tables"
