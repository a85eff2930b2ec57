#!/usr/bin/env bash
# A bundled campaign (harness/campaigns/*.toml) gives sane numbers (issue 37): a few runs of it, shortened,
# each finished with status ok and its filter's error bounded. Usage:
#   bundled_campaign_test.sh COSIM FMU_DIR SPEC OUT_DIR RUNS STOP_TIME P95_BOUND_DEG [--set X=Y ...]
# The metric is the spec's `filter_error` (the filter's attitude against the truth); its p95 over each run
# must lie below P95_BOUND_DEG. Before the epoch draw moved the on-board clock and element sets with the
# truth's date, these runs gave 134-164 deg.
set -euo pipefail
cosim=$1 fmu_dir=$2 spec=$3 out=$4 runs=$5 stop=$6 bound=$7
shift 7
rm -rf "$out"
"$cosim" campaign "$spec" --runs "$runs" --stop-time "$stop" --fmu-dir "$fmu_dir" --output "$out" --no-figures "$@" \
  > "$out.log" 2>&1 || { cat "$out.log"; exit 1; }
table=$out/results.csv
[ -f "$table" ] || { echo "no $table"; cat "$out.log"; exit 1; }
# The columns by name (the table is plain CSV; no drawn value holds a comma).
awk -F, -v bound="$bound" '
  NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i
            if (!("filter_error.p95" in col) || !("status" in col)) { print "no filter_error.p95 or status column"; bad = 1; exit }
            next }
  { status = $col["status"]; p95 = $col["filter_error.p95"]; ++rows
    printf "run %s: status %s, filter_error p95 %s deg (bound %s)\n", $col["run"], status, p95, bound
    if (status != "ok") { print "  run " $col["run"] " did not finish: " $0; bad = 1 }
    else if (p95 == "" || p95 + 0 >= bound + 0) { print "  run " $col["run"] "'"'"'s filter error is above the bound"; bad = 1 } }
  END { if (rows == 0) { print "no runs in the table"; bad = 1 } exit bad }' "$table"
