#!/usr/bin/env python3
"""Statistics of the attitude filter from a `cosim run` CSV (docs/filter.md shows the command lines).

Reads the columns env.q_true[1..4], env.omega_body[1..3], env.irradiance (optional: all sunlit without it),
est.q_est[1..4], est.valid, est.q_filt[1..4], est.filter_valid, est.attitude_bound, est.omega_filt[1..3],
and prints, for rows with time >= --from: the single-frame and the filter's attitude error (median, p95)
in sunlit and eclipse rows, the fraction of rows whose filter error is within the 3-sigma bound, and the
rate error. Standard library only; the attitude error is 2 acos|q_a . q_b| (q and -q are one attitude).
"""
import argparse
import csv
import math


def angle_deg(qa, qb):
    dot = abs(sum(a * b for a, b in zip(qa, qb)))
    na = math.sqrt(sum(a * a for a in qa))
    nb = math.sqrt(sum(b * b for b in qb))
    return 2.0 * math.degrees(math.acos(min(1.0, dot / (na * nb))))


def pct(values, p):
    if not values:
        return float("nan")
    v = sorted(values)
    return v[min(len(v) - 1, int(p * (len(v) - 1) + 0.5))]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("csv")
    ap.add_argument("--from", dest="t_from", type=float, default=0.0)
    ap.add_argument("--trace", help="write time, filter error, 3-sigma bound, single-frame error (deg), lit")
    ap.add_argument("--every", type=int, default=1, help="write every n-th row to the trace")
    args = ap.parse_args()
    trace = open(args.trace, "w") if args.trace else None
    rows = list(csv.DictReader(open(args.csv)))
    q = lambda r, name: [float(r[f"{name}[{i}]"]) for i in range(1, 5)]
    single = {"lit": [], "dark": []}
    filt = {"lit": [], "dark": []}
    covered = total = filter_valid = valid = 0
    rate_err = []
    for r in rows:
        t = float(r["time"])
        if t < args.t_from:
            continue
        total += 1
        lit = float(r.get("env.irradiance", 1.0)) > 0.0
        key = "lit" if lit else "dark"
        truth = q(r, "env.q_true")
        if float(r["est.valid"]) > 0.5:
            valid += 1
            single[key].append(angle_deg(truth, q(r, "est.q_est")))
        err = angle_deg(truth, q(r, "est.q_filt"))
        if float(r["est.filter_valid"]) > 0.5:
            filter_valid += 1
            filt[key].append(err)
        bound = math.degrees(float(r["est.attitude_bound"]))
        covered += err <= bound
        if trace and total % args.every == 0:
            single_err = angle_deg(truth, q(r, "est.q_est")) if float(r["est.valid"]) > 0.5 else float("nan")
            trace.write(f"{t:.2f} {err:.4f} {bound:.4f} {single_err:.4f} {int(lit)}\n")
        if "env.omega_body[1]" in r:
            w = [float(r[f"est.omega_filt[{i}]"]) - float(r[f"env.omega_body[{i}]"]) for i in range(1, 4)]
            rate_err.append(math.degrees(math.sqrt(sum(x * x for x in w))))
    print(f"rows {total} from t = {args.t_from:g} s; single-frame valid {valid}, filter valid {filter_valid}")
    for key in ("lit", "dark"):
        print(f"{key:5s} single-frame median {pct(single[key], 0.5):.3f} p95 {pct(single[key], 0.95):.3f} deg (n {len(single[key])});"
              f" filter median {pct(filt[key], 0.5):.3f} p95 {pct(filt[key], 0.95):.3f} deg (n {len(filt[key])})")
    print(f"3-sigma bound covers the filter error in {100.0 * covered / max(total, 1):.2f} % of rows")
    if rate_err:
        print(f"rate error median {pct(rate_err, 0.5):.4f} p95 {pct(rate_err, 0.95):.4f} deg/s")
    last = rows[-1]
    extra = [c for c in ("est.mag_offset_filt[1]", "est.mag_offset_filt[2]", "est.mag_offset_filt[3]",
                         "est.panel_scale_filt", "est.filter_resets") if c in last]
    if extra:
        print("last row: " + ", ".join(f"{c} = {float(last[c]):.5g}" for c in extra))


if __name__ == "__main__":
    main()
