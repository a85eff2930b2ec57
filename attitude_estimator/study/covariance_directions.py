#!/usr/bin/env python3
"""Where a filter is over- or under-confident: the error split along the eigenvectors of its covariance.

For each row of a `cosim run` or `cosim campaign --run N` CSV in the second half of the run (the second orbit of a
two-orbit run) with a running filter, the attitude error dtheta (q_true (x) q_filt^-1 in Shuster's order, as
consistency_spans.py) is projected on the eigenvectors of P_theta = L L^T (thin to wide) and divided by their
sigma. A consistent filter gives a mean square of 1 along each. Printed per phase (env.irradiance > 0: sunlit):
NEES/dof, those three mean squares, the median sigmas, and how the thinnest direction lies against the body axes,
the rate (env.omega_body), the sun and the field in body axes (median |cos|). attitude_estimator/docs/filter.md,
"Fast tumbles", was measured with it. Needs numpy.
"""
import argparse
import csv

import numpy as np


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    head = rows[0]
    data = np.array([[float(x) if x not in ("", "nan") else np.nan for x in r] for r in rows[1:]])
    return lambda name: data[:, head.index(name)]


def vectors(col, name, n):
    return np.stack([col(f"{name}[{k}]") for k in range(1, n + 1)], 1)


def delta_theta(q_true, q_filt):
    x1, y1, z1, w1 = q_true.T
    x2, y2, z2, w2 = -q_filt[:, 0], -q_filt[:, 1], -q_filt[:, 2], q_filt[:, 3]
    d = np.stack([w1 * x2 + w2 * x1 - (y1 * z2 - z1 * y2), w1 * y2 + w2 * y1 - (z1 * x2 - x1 * z2),
                  w1 * z2 + w2 * z1 - (x1 * y2 - y1 * x2)], 1)
    sign = np.where((w1 * w2 - (x1 * x2 + y1 * y2 + z1 * z2)) < 0, -2.0, 2.0)
    return d * sign[:, None]


def covariance(l):
    L = np.array([[l[0], 0, 0], [l[1], l[2], 0], [l[3], l[4], l[5]]])
    return L @ L.T


def unit(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv", help="a run's CSV with env.q_true, est.q_filt, est.attitude_cov_sqrt, env.irradiance, "
                                    "env.omega_body, env.sun_body, env.mag_body")
    args = parser.parse_args()
    col = read(args.csv)
    t = col("time")
    late = t >= t[-1] / 2
    d = delta_theta(vectors(col, "env.q_true", 4), vectors(col, "est.q_filt", 4))
    factor = vectors(col, "est.attitude_cov_sqrt", 6)
    rate, sun, field = (vectors(col, n, 3) for n in ("env.omega_body", "env.sun_body", "env.mag_body"))
    sunlit = col("env.irradiance") > 0
    for phase, keep in (("sunlit", late & sunlit), ("eclipse", late & ~sunlit)):
        rows = np.where(keep & (factor[:, 0] > 0))[0]
        if rows.size == 0:
            print(f"{phase}: no rows")
            continue
        z2, sigma, thin = [], [], []
        for i in rows:
            value, vec = np.linalg.eigh(covariance(factor[i]))
            z2.append((vec.T @ d[i]) ** 2 / value)
            sigma.append(np.degrees(np.sqrt(value)))
            thin.append(vec[:, 0])
        z2, sigma, thin = np.array(z2), np.array(sigma), np.array(thin)
        nees = z2.sum(1).mean() / 3
        cos = lambda other: np.median(np.abs(np.sum(thin * unit(other[rows]), 1)))
        print(f"{phase}: {rows.size} rows, NEES/dof {nees:.2f}; mean z^2 (thin, mid, wide) "
              + ", ".join(f"{v:.2f}" for v in z2.mean(0)) + "; sigma deg " + ", ".join(f"{v:.3f}" for v in np.median(sigma, 0))
              + "; thin |cos| body x, y, z " + ", ".join(f"{v:.2f}" for v in np.median(np.abs(thin), 0))
              + f", rate {cos(rate):.2f}, sun {cos(sun):.2f}, field {cos(field):.2f}")


if __name__ == "__main__":
    main()
