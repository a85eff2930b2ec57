#!/usr/bin/env bash
# One scene of issue 39: leo_orbit.ssd moved by scene.py, two orbits at 1 s rows, then scene_stats.py over
# the second orbit. Extra `--set` arguments after `--` (a filter tuning) go to cosim as they are.
#   run_scene.sh OUT.csv [scene.py arguments | bundled] [-- name=value ...]
# BUILD (default build) holds bin/cosim and the FMUs.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${BUILD:-$root/build}
out=$1
shift
scene=()
extra=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do scene+=("$1"); shift; done
[ $# -gt 0 ] && shift
extra=("$@")
args=()
if [ "${scene[0]:-}" = bundled ]; then  # leo_orbit.ssd as it is, its start attitude and rate too
    period=5763.86
else
    period=$(python3 "$here/scene.py" "${scene[@]}" 2>&1 >/dev/null | sed -n 's/.*period \([0-9.]*\) s/\1/p')
    while IFS= read -r line; do args+=(--set "$line"); done < <(python3 "$here/scene.py" "${scene[@]}" 2>/dev/null)
fi
for e in "${extra[@]}"; do args+=(--set "$e"); done
cols="env.q_true[1],env.q_true[2],env.q_true[3],env.q_true[4],est.q_filt[1],est.q_filt[2],est.q_filt[3],est.q_filt[4]"
cols+=",est.attitude_cov_sqrt[1],est.attitude_cov_sqrt[2],est.attitude_cov_sqrt[3],est.attitude_cov_sqrt[4]"
cols+=",est.attitude_cov_sqrt[5],est.attitude_cov_sqrt[6],est.attitude_bound,env.irradiance,est.filter_valid"
cols+=",est.filter_resets,est.mag_cal_valid,env.omega_body[1],env.omega_body[2],env.omega_body[3]"
cols+=",est.omega_filt[1],est.omega_filt[2],est.omega_filt[3],est.valid,est.q_est[1],est.q_est[2],est.q_est[3],est.q_est[4]"
stop=$(python3 -c "print(2 * $period)")
"$build/bin/cosim" run "$root/harness/systems/leo_orbit.ssd" --fmu-dir "$build/fmus" --stop-time "$stop" \
    --output-interval 1 --output "$out" --columns "$cols" "${args[@]}" >/dev/null
python3 "$here/scene_stats.py" "$out" --from "$period"
