#!/usr/bin/env python3
"""Attitude statistics of a leo_orbit run with the on-board references (docs/onboard_references.md).

Beside filter_stats.py's figures (reused from it: the attitude angle and the percentiles), for rows with
time >= --from: the filter's error median and p95 sunlit, p95 in eclipse, the chi2(3) 99 % coverage (the
share of valid rows with dtheta^T P^-1 dtheta <= 11.34: 99 % for a consistent filter; the 3-sigma coverage
against 3 sqrt(tr P) is printed beside it, but reads 100 % for an overconfident filter too), the mean
normalized error per degree of freedom sunlit and in eclipse, dtheta^T P^-1 dtheta / 3 with P from the
filter's est.attitude_cov_sqrt (1 for a consistent filter, below 1 for a pessimistic one, above for an
overconfident one; |dtheta|^2 / tr P with tr P = (attitude_bound / 3)^2 where the factor is not in the
CSV), and the on-board references' errors against the
truth's (est.ref_sun vs env.sun_eci, est.ref_mag vs env.mag_eci: direction, and the field's vector error
per axis, RMS). Prints one table row when --row NAME is given. Standard library only.
"""
import argparse
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from filter_stats import angle_deg, pct  # noqa: E402

CHI2_3DOF_99 = 11.344866730144373  # chi2(3) at 99 % (analysis/run_measures.hpp, chi2_3dof_99)


def vec(r, name):
    return [float(r[f"{name}[{i}]"]) for i in range(1, 4)]


def direction_deg(a, b):
    na = math.sqrt(sum(x * x for x in a))
    nb = math.sqrt(sum(x * x for x in b))
    c = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    return math.degrees(math.atan2(math.sqrt(sum(x * x for x in c)), sum(x * y for x, y in zip(a, b))))


def error_vector(qt, qf):
    """dtheta of q_true = dq (x) q_filt: 2 vec(dq), dq = q_true (x) q_filt^-1, scalar-last (as the e2e test)."""
    x1, y1, z1, w1 = qt
    x2, y2, z2, w2 = -qf[0], -qf[1], -qf[2], qf[3]
    d = [w1 * x2 + w2 * x1 - (y1 * z2 - z1 * y2), w1 * y2 + w2 * y1 - (z1 * x2 - x1 * z2),
         w1 * z2 + w2 * z1 - (x1 * y2 - y1 * x2)]
    s = -2.0 if w1 * w2 - (x1 * x2 + y1 * y2 + z1 * z2) < 0 else 2.0
    return [s * v for v in d]


def nees_per_dof(d, l):
    """|L^-1 d|^2 / 3 with L the lower triangle (by rows: l00, l10, l11, l20, l21, l22) of P = L L^T."""
    z0 = d[0] / l[0]
    z1 = (d[1] - l[1] * z0) / l[2]
    z2 = (d[2] - l[3] * z0 - l[4] * z1) / l[5]
    return (z0 * z0 + z1 * z1 + z2 * z2) / 3.0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("csv")
    ap.add_argument("--from", dest="t_from", type=float, default=0.0)
    ap.add_argument("--row", help="print a markdown table row with this name")
    args = ap.parse_args()
    lit, dark, nees, sun_err, mag_err, mag_axis = [], [], [], [], [], []
    nees_lit, nees_dark = [], []
    covered = total = 0
    chi2_in = chi2_n = 0
    for r in csv.DictReader(open(args.csv)):
        if float(r["time"]) < args.t_from:
            continue
        total += 1
        q = lambda name: [float(r[f"{name}[{i}]"]) for i in range(1, 5)]
        err = angle_deg(q("env.q_true"), q("est.q_filt"))
        bound = math.degrees(float(r["est.attitude_bound"]))
        covered += err <= bound
        if float(r["est.filter_valid"]) > 0.5:
            (lit if float(r["env.irradiance"]) > 0.0 else dark).append(err)
            if bound > 0.0:
                nees.append((err / (bound / 3.0)) ** 2)
            if "est.attitude_cov_sqrt[1]" in r:
                l = [float(r[f"est.attitude_cov_sqrt[{i}]"]) for i in range(1, 7)]
                if l[0] > 0 and l[2] > 0 and l[5] > 0:
                    value = nees_per_dof(error_vector(q("env.q_true"), q("est.q_filt")), l)
                    (nees_lit if float(r["env.irradiance"]) > 0.0 else nees_dark).append(value)
                    chi2_n += 1
                    chi2_in += 3.0 * value <= CHI2_3DOF_99
        if "est.ref_sun[1]" in r:
            sun_err.append(direction_deg(vec(r, "est.ref_sun"), vec(r, "env.sun_eci")))
            m, t = vec(r, "est.ref_mag"), vec(r, "env.mag_eci")
            mag_err.append(direction_deg(m, t))
            mag_axis.extend((a - b) ** 2 for a, b in zip(m, t))
    coverage = 100.0 * covered / max(total, 1)
    chi2_coverage = 100.0 * chi2_in / chi2_n if chi2_n else float("nan")
    mean_nees = sum(nees) / max(len(nees), 1)
    rms_axis = math.sqrt(sum(mag_axis) / max(len(mag_axis), 1)) * 1e9
    print(f"rows {total} from t = {args.t_from:g} s")
    print(f"filter sunlit median {pct(lit, 0.5):.3f} p95 {pct(lit, 0.95):.3f} deg (n {len(lit)}); "
          f"eclipse p95 {pct(dark, 0.95):.3f} deg (n {len(dark)})")
    print(f"chi2(3) 99 % coverage {chi2_coverage:.2f} % (n {chi2_n}); 3-sigma coverage {coverage:.2f} %; "
          f"mean |dtheta|^2 / tr P {mean_nees:.3f}")
    mean = lambda v: sum(v) / len(v) if v else float("nan")
    if nees_lit or nees_dark:
        print(f"NEES per dof (full covariance): sunlit {mean(nees_lit):.3f} (n {len(nees_lit)}), "
              f"eclipse {mean(nees_dark):.3f} (n {len(nees_dark)})")
    if sun_err:
        print(f"sun reference error median {pct(sun_err, 0.5):.4f} max {max(sun_err):.4f} deg; field reference "
              f"direction error median {pct(mag_err, 0.5):.3f} p95 {pct(mag_err, 0.95):.3f} deg, "
              f"RMS per axis {rms_axis:.0f} nT")
    if args.row:
        print(f"| {args.row} | {pct(lit, 0.5):.3f}° | {pct(lit, 0.95):.3f}° | {pct(dark, 0.95):.3f}° | {chi2_coverage:.1f} % | "
              f"{mean(nees_lit):.2f} | {mean(nees_dark):.2f} | {pct(mag_err, 0.95) if mag_err else float('nan'):.3f}° | "
              f"{rms_axis:.0f} |")


if __name__ == "__main__":
    main()
