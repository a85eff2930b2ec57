#!/usr/bin/env python3
"""The field error a filter is given, turned into inertial axes, and its share along the angular momentum.

For the second orbit (time >= --from) of a `cosim campaign ... --run N` CSV, per phase (env.irradiance > 0:
sunlit): the error of the field the filter sees (est.mag_field against env.mag_body, body axes) plus its
reference's (env.mag_eci against est.ref_mag, turned into the body), turned into inertial axes with the truth's
attitude; its mean along the truth's angular momentum direction h (J omega, J the 3U's inertia of leo_orbit.ssd),
and the rms of its means over 60, 300 and 900 rows against what a white noise of --sigma per axis at --rate Hz
would leave. A tumble averages what turns with the body, not what lies along h: docs/filter.md, "Fast tumbles".
Needs numpy.
"""
import argparse
import csv

import numpy as np

J = np.array([[0.0405, 0.00015, -0.0002], [0.00015, 0.0398, 0.0001], [-0.0002, 0.0001, 0.0072]])


def load(path):
    rows = list(csv.reader(open(path, newline="")))
    head = rows[0]
    data = np.array([[float(x) if x not in ("", "nan") else np.nan for x in r] for r in rows[1:]])
    return lambda name, n: np.stack([data[:, head.index(f"{name}[{k}]")] for k in range(1, n + 1)], 1), \
        lambda name: data[:, head.index(name)]


def attitude_matrix(q):  # scalar-last, Shuster's: inertial to body
    x, y, z, w = q
    v = np.array([x, y, z])
    s = np.array([[0, -z, y], [z, 0, -x], [-y, x, 0]])
    return (w * w - v @ v) * np.eye(3) + 2 * np.outer(v, v) - 2 * w * s


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv")
    parser.add_argument("--from", dest="start", type=float, default=5900.0)
    parser.add_argument("--sigma", nargs=2, type=float, default=[14.2e-6, 3.47e-6],
                        help="the field's weight per axis, sunlit and eclipse, T (leo_orbit: 14 and 2.5 uT with 2.4 uT)")
    parser.add_argument("--rate", type=float, default=20.0, help="field updates per second")
    args = parser.parse_args()
    vec, col = load(args.csv)
    t = col("time")
    field, truth_body = vec("est.mag_field", 3), vec("env.mag_body", 3)
    ref, truth_ref = vec("est.ref_mag", 3), vec("env.mag_eci", 3)
    q, rate = vec("env.q_true", 4), vec("env.omega_body", 3)
    sunlit = col("env.irradiance") > 0
    for (phase, keep), sigma in zip((("sunlit", sunlit), ("eclipse", ~sunlit)), args.sigma):
        rows = keep & (t >= args.start) & np.isfinite(field).all(1) & (np.linalg.norm(field, axis=1) > 0)
        a = np.array([attitude_matrix(x) for x in q[rows]])
        error = (field[rows] - truth_body[rows]) * 1e9 + np.einsum("nij,nj->ni", a, truth_ref[rows] - ref[rows]) * 1e9
        h = (J @ rate[rows].T).T
        h /= np.linalg.norm(h, axis=1, keepdims=True)
        error_i = np.einsum("nji,nj->ni", a, error)
        h_i = np.einsum("nji,nj->ni", a, h)
        along = np.mean(np.sum(error_i * h_i, 1))
        white = sigma * 1e9 / np.sqrt(rows.sum() * args.rate)
        print(f"{phase}: {rows.sum()} rows; mean along h {along:.1f} nT (white noise over the span: {white:.1f} nT); "
              f"body-axes mean " + ", ".join(f"{v:.1f}" for v in error.mean(0)) + " nT")
        for width in (60, 300, 900):
            n = len(error_i) // width
            if n < 1:
                continue
            means = np.array([error_i[i * width:(i + 1) * width].mean(0) for i in range(n)])
            print(f"  {width}-row means: rms {np.sqrt((means ** 2).mean()):.1f} nT per axis "
                  f"(white: {sigma * 1e9 / np.sqrt(width * args.rate):.1f})")


if __name__ == "__main__":
    main()
