#!/usr/bin/env python3
"""The filter's consistency per span of a `cosim run` CSV: NEES/dof, 3-sigma coverage, median and p95 error.

Reads env.q_true[1..4], est.q_filt[1..4], est.attitude_cov_sqrt[1..6] (lower Cholesky factor of P_theta by
rows), est.attitude_bound and, optionally, env.irradiance. Spans (s, from the start of the run): the first
30 minutes, the rest of the first orbit, the second orbit (--orbit, leo_orbit's period by default).
NEES/dof is |L^-1 dtheta|^2 / 3 averaged over the span's rows with a running filter, dtheta from
q_true (x) q_filt^-1 in Shuster's order (as tests/e2e/e2e_filter_consistency_test.cpp). Standard library only.
"""
import argparse
import csv
import math


def pct(values, p):
    if not values:
        return float("nan")
    v = sorted(values)
    return v[min(len(v) - 1, int(p * (len(v) - 1) + 0.5))]


def delta_theta(qt, qf):
    x1, y1, z1, w1 = qt
    x2, y2, z2, w2 = -qf[0], -qf[1], -qf[2], qf[3]
    d = [w1 * x2 + w2 * x1 - (y1 * z2 - z1 * y2), w1 * y2 + w2 * y1 - (z1 * x2 - x1 * z2),
         w1 * z2 + w2 * z1 - (x1 * y2 - y1 * x2)]
    s = -2.0 if (w1 * w2 - (x1 * x2 + y1 * y2 + z1 * z2)) < 0 else 2.0
    return [v * s for v in d]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("csv", nargs="+")
    ap.add_argument("--orbit", type=float, default=5763.86)
    ap.add_argument("--first", type=float, default=1800.0, help="length of the first span (s)")
    args = ap.parse_args()
    spans = [("first 30 min", 0.0, args.first), ("rest of orbit 1", args.first, args.orbit),
             ("orbit 2", args.orbit, 2 * args.orbit)]
    print("| run | span | rows | NEES/dof | 3σ coverage | median | p95 |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for path in args.csv:
        rows = list(csv.DictReader(open(path)))
        for name, t0, t1 in spans:
            nees, err, covered, n = [], [], 0, 0
            for r in rows:
                t = float(r["time"])
                if t < t0 or t >= t1:
                    continue
                l = [float(r[f"est.attitude_cov_sqrt[{i}]"]) for i in range(1, 7)]
                if not (l[0] > 0 and l[2] > 0 and l[5] > 0):
                    continue
                d = delta_theta([float(r[f"env.q_true[{i}]"]) for i in range(1, 5)],
                                [float(r[f"est.q_filt[{i}]"]) for i in range(1, 5)])
                z0 = d[0] / l[0]
                z1 = (d[1] - l[1] * z0) / l[2]
                z2 = (d[2] - l[3] * z0 - l[4] * z1) / l[5]
                nees.append((z0 * z0 + z1 * z1 + z2 * z2) / 3.0)
                e = math.sqrt(sum(v * v for v in d))
                err.append(math.degrees(e))
                covered += e <= float(r["est.attitude_bound"])
                n += 1
            if not n:
                continue
            print(f"| {path.rsplit('/', 1)[-1]} | {name} | {n} | {sum(nees) / n:.2f} | {100.0 * covered / n:.1f} % | "
                  f"{pct(err, 0.5):.3f}° | {pct(err, 0.95):.3f}° |")


if __name__ == "__main__":
    main()
