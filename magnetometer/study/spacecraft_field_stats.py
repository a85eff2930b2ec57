#!/usr/bin/env python3
"""The spacecraft's own field in a `cosim run` CSV of leo_orbit (magnetometer/README.md shows the runs).

Reads time, env.q_true[1..4], env.irradiance, est.q_filt[1..4], est.filter_valid, est.attitude_bound,
est.filter_resets, est.mag_offset_filt[1..3] and mag.mag_spacecraft[1..3], and prints:
  - |mag_spacecraft| over the first orbit (min, median, max, nT);
  - the filter's attitude error from --from on, sunlit median and p95, eclipse p95 (deg), and the fraction
    of rows within the 3-sigma bound;
  - the filter's offset estimate b = mag_offset_filt / S at the end of the run against the constant bias
    the sensor reads, M (B_dipole) + V_os / S, computed here from the dipole formula (--dipole, A.m2 along
    body z at the box centre, sensor at --sensor), the cross-axis matrix and the bridge offset: the
    residual |b - truth| (nT), without set/reset pulses (--pulses 0, est.mag_set_reset_samples = 0), where the
    offset state is constant in the field; with pulses it holds what is left of the bridge offset, and the
    dipole's field, which flips with the Earth's, stays in the measured field.
Standard library only.
"""
import argparse
import csv
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "attitude_estimator", "study"))
from filter_stats import angle_deg, pct  # noqa: E402  (the estimator study's attitude error and percentile)


def dipole_field(m, r):
    d = math.sqrt(sum(x * x for x in r))
    u = [x / d for x in r]
    mu = sum(a * b for a, b in zip(m, u))
    return [1e-7 / d**3 * (3.0 * ui * mu - mi) for ui, mi in zip(u, m)]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("csv")
    ap.add_argument("--from", dest="t_from", type=float, default=5764.0, help="attitude statistics from (s)")
    ap.add_argument("--orbit", type=float, default=5764.0, help="orbital period (s): field statistics over [0, orbit]")
    ap.add_argument("--dipole", type=float, default=0.0, help="residual dipole along body z (A.m2)")
    ap.add_argument("--sensor", type=float, nargs=3, default=[0.01, 0.01, 0.11], help="sensor position (m)")
    ap.add_argument("--cross-axis", type=float, default=0.003)
    ap.add_argument("--bridge-offset", type=float, default=0.02, help="V")
    ap.add_argument("--sensitivity", type=float, default=1e4, help="V/T, sensor and estimator")
    ap.add_argument("--pulses", type=int, default=1, help="est.mag_set_reset_samples of the run (0: no pulses)")
    args = ap.parse_args()
    rows = list(csv.DictReader(open(args.csv)))
    q = lambda r, name: [float(r[f"{name}[{i}]"]) for i in range(1, 5)]
    v3 = lambda r, name: [float(r[f"{name}[{i}]"]) for i in range(1, 4)]

    field = [math.sqrt(sum(b * b for b in v3(r, "mag.mag_spacecraft"))) * 1e9 for r in rows
             if float(r["time"]) <= args.orbit]
    print(f"|mag_spacecraft| over [0, {args.orbit:g}] s: min {min(field):.1f} median {pct(field, 0.5):.1f} "
          f"max {max(field):.1f} nT ({len(field)} rows)")

    lit, dark = [], []
    covered = total = 0
    for r in rows:
        if float(r["time"]) < args.t_from or float(r["est.filter_valid"]) < 0.5:
            continue
        err = angle_deg(q(r, "env.q_true"), q(r, "est.q_filt"))
        (lit if float(r["env.irradiance"]) > 0.0 else dark).append(err)
        total += 1
        covered += err <= math.degrees(float(r["est.attitude_bound"]))
    print(f"filter from {args.t_from:g} s: sunlit median {pct(lit, 0.5):.3f} p95 {pct(lit, 0.95):.3f} deg, "
          f"eclipse p95 {pct(dark, 0.95):.3f} deg, 3-sigma coverage {100.0 * covered / max(total, 1):.2f} % "
          f"({total} rows), resets {float(rows[-1]['est.filter_resets']):g}")

    c = args.cross_axis
    b_dip = dipole_field([0.0, 0.0, args.dipole], args.sensor)
    m_rows = [[1.0, c, c], [c, 1.0, c], [c, c, 1.0]]
    m_b_dip = [sum(m_rows[i][j] * b_dip[j] for j in range(3)) for i in range(3)]
    est = [v / args.sensitivity for v in v3(rows[-1], "est.mag_offset_filt")]
    norm = lambda v: math.sqrt(sum(x * x for x in v))
    if args.pulses:
        # Set/reset takes the bridge offset out; the dipole's field flips with the Earth's and stays.
        # The offset state is modelled as flipping with the pulses, p b; a constant field c fits it only in the
        # readings of one polarity, b = p c: compare b with -M B_dipole (after a reset pulse, p = -1).
        locked = norm([a + b for a, b in zip(est, m_b_dip)])
        print(f"set/reset: |M B_dipole| = {norm(m_b_dip) * 1e9:.1f} nT; the offset state " +
              ", ".join(f"{x * 1e9:.1f}" for x in est) + f" nT, |b + M B_dipole| = {locked * 1e9:.1f} nT")
        return
    truth = [x + args.bridge_offset / args.sensitivity for x in m_b_dip]
    residual = norm([a - b for a, b in zip(est, truth)])
    print("no pulses: constant bias read (M B_dipole + V_os/S) " + ", ".join(f"{x * 1e9:.1f}" for x in truth) +
          " nT; the filter's offset at the end " + ", ".join(f"{x * 1e9:.1f}" for x in est) +
          f" nT; residual {residual * 1e9:.1f} nT")

if __name__ == "__main__":
    main()
