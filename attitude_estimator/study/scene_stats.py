#!/usr/bin/env python3
"""Per run of a `cosim run` CSV: the filter's figures over a span (issue 39's aims), one table row per file.

Reads env.q_true[1..4], est.q_filt[1..4], est.attitude_cov_sqrt[1..6] (lower Cholesky factor of P_theta by
rows), est.attitude_bound, env.irradiance and, when recorded, est.filter_resets. Over the span [--from, --to):
sunlit and eclipse p95 of the attitude error, NEES/dof (mean of dtheta' P^-1 dtheta / 3), the chi2(3) 99 %
coverage (share of rows with dtheta' P^-1 dtheta <= 11.345), both also per phase (sunlit, eclipse), the resets in the span; over the whole run the
first time the 3-sigma bound is below 2 deg. Standard library only; dtheta and percentiles from consistency_spans.py.
"""
import argparse
import csv
import math

from consistency_spans import delta_theta, pct  # the same error and percentile, one definition

CHI2_3_99 = 11.345  # chi2 quantile, 3 degrees of freedom, 0.99


def stats(path, t0, t1):
    rows = csv.DictReader(open(path))
    sun, ecl, nees, first_valid, n_rows, resets0, resets1 = [], [], [], None, 0, None, None
    nees_phase = {True: [], False: []}  # sunlit, eclipse
    for r in rows:
        t = float(r["time"])
        l = [float(r[f"est.attitude_cov_sqrt[{i}]"]) for i in range(1, 7)]
        running = l[0] > 0 and l[2] > 0 and l[5] > 0
        bound = float(r["est.attitude_bound"])
        if first_valid is None and running and bound < math.radians(2.0):
            first_valid = t
        if "est.filter_resets" in r:
            k = float(r["est.filter_resets"])
            if t < t0:
                resets0 = k
            elif t < t1:
                resets1 = k
        if t < t0 or t >= t1:
            continue
        n_rows += 1
        if not running:
            nees.append(float("inf"))
            continue
        d = delta_theta([float(r[f"env.q_true[{i}]"]) for i in range(1, 5)],
                        [float(r[f"est.q_filt[{i}]"]) for i in range(1, 5)])
        z0 = d[0] / l[0]
        z1 = (d[1] - l[1] * z0) / l[2]
        z2 = (d[2] - l[3] * z0 - l[4] * z1) / l[5]
        nees.append(z0 * z0 + z1 * z1 + z2 * z2)
        e = math.degrees(math.sqrt(sum(v * v for v in d)))
        lit = float(r["env.irradiance"]) > 0
        (sun if lit else ecl).append(e)
        nees_phase[lit].append(nees[-1])
    finite = [v for v in nees if math.isfinite(v)]

    def per_dof(v):
        return sum(v) / (3 * len(v)) if v else float("nan")

    def cover(v):
        return 100.0 * sum(x <= CHI2_3_99 for x in v) / len(v) if v else float("nan")

    return {
        "nees_sunlit": per_dof(nees_phase[True]),
        "nees_eclipse": per_dof(nees_phase[False]),
        "coverage_sunlit": cover(nees_phase[True]),
        "coverage_eclipse": cover(nees_phase[False]),
        "rows": n_rows,
        "sunlit_p95": pct(sun, 0.95),
        "eclipse_p95": pct(ecl, 0.95),
        "nees_dof": sum(finite) / (3 * len(finite)) if finite else float("nan"),
        "coverage": 100.0 * sum(v <= CHI2_3_99 for v in nees) / len(nees) if nees else float("nan"),
        "first_valid": first_valid,
        "resets": (resets1 or 0) - (resets0 or 0) if resets1 is not None else float("nan"),
    }


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("csv", nargs="+")
    ap.add_argument("--from", dest="t0", type=float, default=5763.86)
    ap.add_argument("--to", dest="t1", type=float, default=1e30)
    a = ap.parse_args()
    print("| run | rows | sunlit p95 | eclipse p95 | NEES/dof | chi2 99 % coverage | NEES/dof sunlit / eclipse | "
          "coverage sunlit / eclipse | first valid (s) | resets |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for path in a.csv:
        s = stats(path, a.t0, a.t1)
        fv = "never" if s["first_valid"] is None else f"{s['first_valid']:.0f}"
        print(f"| {path} | {s['rows']} | {s['sunlit_p95']:.3f} | {s['eclipse_p95']:.3f} | {s['nees_dof']:.2f} | "
              f"{s['coverage']:.1f} % | {s['nees_sunlit']:.2f} / {s['nees_eclipse']:.2f} | "
              f"{s['coverage_sunlit']:.1f} / {s['coverage_eclipse']:.1f} % | {fv} | {s['resets']} |")


if __name__ == "__main__":
    main()
