#!/usr/bin/env python3
"""Where a filter is over- or under-confident: the error split along the eigenvectors of its covariance.

For each row of a `cosim run` or `cosim campaign --run N` CSV in the second half of the run (the second orbit of a
two-orbit run) with a running filter, the attitude error dtheta (q_true (x) q_filt^-1 in Shuster's order,
consistency_spans.delta_theta) is projected on the eigenvectors of P_theta = L L^T (thin to wide) and divided by their
sigma. A consistent filter gives a mean square of 1 along each. Printed per phase (env.irradiance > 0: sunlit):
NEES/dof, those three mean squares, the median sigmas, and how the thinnest direction lies against the body axes,
the rate (env.omega_body), the sun and the field in body axes (median |cos|). attitude_estimator/docs/filter.md,
"Fast tumbles", was measured with it. Needs numpy.
"""
import argparse
import csv

import numpy as np

from consistency_spans import delta_theta  # the error's convention, shared with the consistency figures


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    head = rows[0]
    data = np.array([[float(x) if x not in ("", "nan") else np.nan for x in r] for r in rows[1:]])
    return lambda name: data[:, head.index(name)]


def vectors(col, name, n):
    return np.stack([col(f"{name}[{k}]") for k in range(1, n + 1)], 1)


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
    d = np.array([delta_theta(qt, qf) for qt, qf in zip(vectors(col, "env.q_true", 4), vectors(col, "est.q_filt", 4))])
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
