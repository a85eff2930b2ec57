#!/usr/bin/env bash
# The attitude error budget of the bundled leo_orbit (README "How well it knows its attitude",
# attitude_estimator/docs/onboard_references.md): two orbits of the system as bundled and with one error
# source changed at a time, each summarized over the second orbit by reference_stats.py (the filter's error
# sunlit and in eclipse, chi2(3) 99 % coverage, normalized error). The rows:
#   truth-fed            the environment's true sun and field wired into the estimator (reference_source =
#                        inputs), as leo_orbit did before the on-board references: the optimistic reference
#   bundled              on-board references from a 24 h-old element set, IGRF-14 to degree 8, a 0.05 A.m2
#                        residual dipole and the plant's currents read by the magnetometer
#   tle 0 h / 72 h       the on-board element set the truth's own / 72 h older (est.uplink_age)
#   degree 13 / 1        the on-board field model to degree 13 (the truth's) / a dipole
#   dipole 0 / 0.2       the spacecraft's residual dipole, A.m2
#   no spacecraft field  the magnetometer reads the Earth's field alone (mag.read_spacecraft_field = false)
# Usage, from the repository root after a build: bash attitude_estimator/study/error_budget.sh OUT_DIR
set -euo pipefail
out=${1:?output directory}
mkdir -p "$out"
ssd=harness/systems/leo_orbit.ssd
study=attitude_estimator/study

# The truth-fed system: the estimator's reference inputs declared and connected to the environment's truth.
fed=$out/leo_orbit_truth_fed.ssd
python3 - "$ssd" "$fed" <<'PY'
import sys
s = open(sys.argv[1]).read()
conn = lambda name, unit: f'          <ssd:Connector name="{name}" kind="input"><ssc:Real unit="{unit}"/></ssd:Connector>\n'
inputs = "".join(conn(f"sun_ref[{i}]", "1") for i in (1, 2, 3)) + conn("sun_distance", "m") + \
    "".join(conn(f"mag_ref[{i}]", "T") for i in (1, 2, 3))
anchor = '          <ssd:Connector name="v_mag_ref" kind="input"><ssc:Real unit="V"/></ssd:Connector>\n'
assert anchor in s
s = s.replace(anchor, anchor + inputs, 1)
wire = lambda a, b: f'      <ssd:Connection startElement="env" startConnector="{a}" endElement="est" endConnector="{b}"/>\n'
links = "".join(wire(f"sun_eci[{i}]", f"sun_ref[{i}]") for i in (1, 2, 3)) + wire("sun_distance", "sun_distance") + \
    "".join(wire(f"mag_eci[{i}]", f"mag_ref[{i}]") for i in (1, 2, 3))
s = s.replace("    </ssd:Connections>", links + "    </ssd:Connections>", 1)
open(sys.argv[2], "w").write(s)
PY

cols=(env.q_true[1] env.q_true[2] env.q_true[3] env.q_true[4] env.irradiance env.sun_eci[1] env.sun_eci[2]
  env.sun_eci[3] env.mag_eci[1] env.mag_eci[2] env.mag_eci[3] est.q_filt[1] est.q_filt[2] est.q_filt[3]
  est.q_filt[4] est.filter_valid est.attitude_bound est.attitude_cov_sqrt[1] est.attitude_cov_sqrt[2]
  est.attitude_cov_sqrt[3] est.attitude_cov_sqrt[4] est.attitude_cov_sqrt[5] est.attitude_cov_sqrt[6]
  est.ref_sun[1] est.ref_sun[2] est.ref_sun[3] est.ref_mag[1] est.ref_mag[2] est.ref_mag[3])
echo "| configuration | sunlit median | sunlit p95 | eclipse p95 | χ²(3) 99 % coverage | NEES/dof sunlit | NEES/dof eclipse | field reference p95 | field reference RMS/axis (nT) |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
run() {  # name, system, settings...
  local name=$1 system=$2
  shift 2
  ./build/bin/cosim run "$system" --stop-time 11528 --output-interval 1 "$@" --columns "${cols[@]}" \
    --output "$out/$name.csv" > "$out/$name.log"
  python3 "$study/reference_stats.py" "$out/$name.csv" --from 5764 --row "$name" | tail -n 1
}
run "truth-fed" "$fed" --set est.reference_source=inputs
run "bundled (24 h, degree 8, dipole 0.05)" "$ssd"
run "tle 0 h" "$ssd" --set est.uplink_age=0
run "tle 72 h" "$ssd" --set est.uplink_age=259200
run "degree 13" "$ssd" --set est.field_degree=13
run "degree 1 (dipole)" "$ssd" --set est.field_degree=1
run "dipole 0" "$ssd" --set "mag.dipole_moment[3]=0"
run "dipole 0.2" "$ssd" --set "mag.dipole_moment[3]=0.2"
run "no spacecraft field" "$ssd" --set mag.read_spacecraft_field=false
