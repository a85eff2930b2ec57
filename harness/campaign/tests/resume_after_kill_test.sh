#!/usr/bin/env bash
# A campaign killed (SIGKILL) while it runs, then resumed with --resume, ends with the same table as
# an uninterrupted campaign (wall times aside), and the rows finished before the kill are not redone.
# Interrupted (SIGINT, Ctrl-C) it stops at the next output point with exit code 130, the run in
# progress not recorded as failed, and resumes the same way.
set -euo pipefail
cosim=$1 spec=$2 fmu_dir=$3 work=$4
source "$(dirname "$0")/drop_wall_time.sh"
rm -rf "$work"
mkdir -p "$work/tmp"
# Its own temporary directory, where each cosim makes its private folder (cosim_<host>_<pid>_XXXXXX).
export TMPDIR="$work/tmp"
args=(campaign "$spec" --fmu-dir "$fmu_dir" --runs 10 --stop-time 20 --no-figures)
"$cosim" "${args[@]}" --output "$work/whole" > /dev/null

"$cosim" "${args[@]}" --output "$work/killed" > /dev/null &
pid=$!
# Kill once at least three rows (header + 2) are on disk, and before the end.
for _ in $(seq 1 6000); do
    [ -f "$work/killed/results.csv" ] && [ "$(wc -l < "$work/killed/results.csv")" -ge 3 ] && break
    sleep 0.01
done
kill -9 "$pid" 2> /dev/null || true
wait "$pid" 2> /dev/null || true
before=$(($(wc -l < "$work/killed/results.csv") - 1))
echo "killed with $before rows written"
[ "$before" -lt 10 ] || { echo "the campaign finished before the kill: nothing was tested"; exit 1; }
cp "$work/killed/results.csv" "$work/before_resume.csv"
# SIGKILL leaves the killed process's private folder (its extracted FMUs); the next cosim on this host sweeps it.
compgen -G "$TMPDIR/cosim_*_${pid}_*" > /dev/null || { echo "the killed campaign left no private folder"; exit 1; }

"$cosim" "${args[@]}" --output "$work/killed" --resume | tee "$work/resume.log"
grep -q "resuming: $before runs" "$work/resume.log" || { echo "resume did not keep the $before finished runs"; exit 1; }
if compgen -G "$TMPDIR/cosim_*_${pid}_*" > /dev/null; then echo "the killed campaign's private folder is left"; exit 1; fi
left=$(find "$TMPDIR" -mindepth 1 -maxdepth 1 | wc -l)
[ "$left" -eq 0 ] || { echo "$left entries left in the temporary directory:"; ls "$TMPDIR"; exit 1; }
diff <(drop_wall_time "$work/whole/results.csv") <(drop_wall_time "$work/killed/results.csv")
# The finished rows are kept byte for byte (their wall times too: they were not run again).
while IFS= read -r row; do
    grep -qxF -- "$row" "$work/killed/results.csv" || { echo "row lost or redone: $row"; exit 1; }
done < <(tail -n +2 "$work/before_resume.csv" | grep -v '^$')
echo "resume lost nothing"

# Ctrl-C: the campaign ends at once (128 + SIGINT), no run is recorded as failed, --resume completes it.
"$cosim" "${args[@]}" --output "$work/interrupted" > /dev/null 2> "$work/interrupted.err" &
pid=$!
for _ in $(seq 1 6000); do
    [ -f "$work/interrupted/results.csv" ] && [ "$(wc -l < "$work/interrupted/results.csv")" -ge 3 ] && break
    sleep 0.01
done
kill -INT "$pid"
rc=0
wait "$pid" || rc=$?
[ "$rc" -eq 130 ] || { echo "exit code $rc after SIGINT, expected 130"; cat "$work/interrupted.err"; exit 1; }
if grep -q ",failed," "$work/interrupted/results.csv"; then echo "the interrupted run was recorded as failed"; exit 1; fi
"$cosim" "${args[@]}" --output "$work/interrupted" --resume > /dev/null
diff <(drop_wall_time "$work/whole/results.csv") <(drop_wall_time "$work/interrupted/results.csv")
echo "interrupt and resume lost nothing"
