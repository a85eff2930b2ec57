#!/usr/bin/env python3
"""Attitude statistics of a leo_orbit run with the on-board references (docs/onboard_references.md).

Beside filter_stats.py's figures (reused from it: the attitude angle and the percentiles), for rows with
time >= --from: the filter's error median and p95 sunlit, p95 in eclipse, the 3-sigma coverage, the mean
normalized error |dtheta|^2 / tr P (tr P = (attitude_bound / 3)^2: 1 for a consistent filter, below 1 for
a pessimistic one, above for an overconfident one), and the on-board references' errors against the
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


def vec(r, name):
    return [float(r[f"{name}[{i}]"]) for i in range(1, 4)]


def direction_deg(a, b):
    na = math.sqrt(sum(x * x for x in a))
    nb = math.sqrt(sum(x * x for x in b))
    c = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    return math.degrees(math.atan2(math.sqrt(sum(x * x for x in c)), sum(x * y for x, y in zip(a, b))))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("csv")
    ap.add_argument("--from", dest="t_from", type=float, default=0.0)
    ap.add_argument("--row", help="print a markdown table row with this name")
    args = ap.parse_args()
    lit, dark, nees, sun_err, mag_err, mag_axis = [], [], [], [], [], []
    covered = total = 0
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
        if "est.ref_sun[1]" in r:
            sun_err.append(direction_deg(vec(r, "est.ref_sun"), vec(r, "env.sun_eci")))
            m, t = vec(r, "est.ref_mag"), vec(r, "env.mag_eci")
            mag_err.append(direction_deg(m, t))
            mag_axis.extend((a - b) ** 2 for a, b in zip(m, t))
    coverage = 100.0 * covered / max(total, 1)
    mean_nees = sum(nees) / max(len(nees), 1)
    rms_axis = math.sqrt(sum(mag_axis) / max(len(mag_axis), 1)) * 1e9
    print(f"rows {total} from t = {args.t_from:g} s")
    print(f"filter sunlit median {pct(lit, 0.5):.3f} p95 {pct(lit, 0.95):.3f} deg (n {len(lit)}); "
          f"eclipse p95 {pct(dark, 0.95):.3f} deg (n {len(dark)})")
    print(f"3-sigma coverage {coverage:.2f} %; mean |dtheta|^2 / tr P {mean_nees:.3f}")
    if sun_err:
        print(f"sun reference error median {pct(sun_err, 0.5):.4f} max {max(sun_err):.4f} deg; field reference "
              f"direction error median {pct(mag_err, 0.5):.3f} p95 {pct(mag_err, 0.95):.3f} deg, "
              f"RMS per axis {rms_axis:.0f} nT")
    if args.row:
        print(f"| {args.row} | {pct(lit, 0.5):.3f} | {pct(lit, 0.95):.3f} | {pct(dark, 0.95):.3f} | {coverage:.1f} % | "
              f"{mean_nees:.2f} | {pct(mag_err, 0.95) if mag_err else float('nan'):.3f} | {rms_axis:.0f} |")


if __name__ == "__main__":
    main()
