#!/usr/bin/env bash
# The runs behind magnetometer/README.md's "What it does": two orbits of the bundled leo_orbit (20 Hz
# rows) with the residual dipole at 0, 0.05 and 0.2 A.m2 along body z, each
#   - as bundled (set/reset pulses every sample, the filter's offset state on),
#   - without pulses (est.mag_set_reset_samples = 0: the offset state is constant in the field and can take
#     the bridge offset and the dipole's field together),
#   - without the offset state (est.filter_offset = false: nothing calibrates the dipole),
# and the bundled system with the spacecraft's field not read (mag.read_spacecraft_field = false).
# Usage, from the repository root after a build: bash magnetometer/study/spacecraft_field_runs.sh OUT_DIR
set -euo pipefail
out=${1:?output directory}
mkdir -p "$out"
cols=(env.q_true[1] env.q_true[2] env.q_true[3] env.q_true[4] env.irradiance est.q_filt[1] est.q_filt[2]
  est.q_filt[3] est.q_filt[4] est.filter_valid est.attitude_bound est.mag_offset_filt[1] est.mag_offset_filt[2]
  est.mag_offset_filt[3] est.filter_resets mag.mag_spacecraft[1] mag.mag_spacecraft[2] mag.mag_spacecraft[3])
run() {  # name, dipole, pulses, settings...
  local name=$out/$1 dipole=$2 pulses=$3
  shift 3
  ./build/bin/cosim run harness/systems/leo_orbit.ssd --stop-time 11528 --output-interval 0.05 \
    --set "mag.dipole_moment[3]=$dipole" --set "est.mag_set_reset_samples=$pulses" "$@" \
    --columns "${cols[@]}" --output "$name.csv" > "$name.log"
  echo "== $name"
  python3 magnetometer/study/spacecraft_field_stats.py "$name.csv" --dipole "$dipole" --pulses "$pulses"
}
for dipole in 0 0.05 0.2; do
  run "dipole${dipole}_bundled" "$dipole" 1
  run "dipole${dipole}_no_pulses" "$dipole" 0
  run "dipole${dipole}_no_offset_state" "$dipole" 1 --set est.filter_offset=false
done
run not_read 0 1 --set mag.read_spacecraft_field=false
