#!/usr/bin/env python3
"""Summary of a fault campaign (harness/campaigns/faults*.toml): per fault type the detection rate, the time
to detect (median, p95), isolation right or wrong, false alarms per orbit in the no-fault control, and the
filter's attitude error after the fault against the same scene without it (the spec's `paired` control).

    python3 attitude_estimator/study/fault_campaign_stats.py RESULTS.csv [RESULTS.csv ...] [--orbit 5764]

A run is a control when its fault selector (the spec's grid draw) is 0 / false. A fault counts as detected
when an element it should name (the open face, the stuck axis, all three axes for a failed strap) is
declared at or after the onset; isolation is right when the elements declared are exactly those. Any
element declared in a control run is a false alarm.
"""
import argparse
import csv
import math
import statistics

ORBIT = 5764.0  # s, leo_orbit's period

# The specs' grid draw (the fault selector), its name, onset column, kind and number of grid values.
SELECTORS = {
    "plant.fault_string_open_face": ("open string", "plant.fault_string_open_onset", "face", 7),
    "mag.fault_stuck_axis": ("stuck axis", "mag.fault_stuck_onset", "axis", 4),
    "mag.fault_strap_failed": ("failed strap", "mag.fault_strap_onset", "strap", 2),
}


def percentile(values, q):
    """Linear interpolation between order statistics (NumPy's default, Hyndman & Fan definition 7)."""
    v = sorted(values)
    if not v:
        return math.nan
    h = (len(v) - 1) * q / 100.0
    lo = math.floor(h)
    hi = min(lo + 1, len(v) - 1)
    return v[lo] + (h - lo) * (v[hi] - v[lo])


def declared(row):
    """(faces, axes) declared, each a dict element -> time (1-based element numbers)."""
    faces = {k: float(row[f"fault_face_time_{k}.final"]) for k in range(1, 7) if float(row[f"fault_face_{k}.final"]) != 0}
    axes = {k: float(row[f"fault_mag_axis_time_{k}.final"]) for k in range(1, 4)
            if float(row[f"fault_mag_axis_{k}.final"]) != 0}
    return faces, axes


def summarize(path):
    rows = [r for r in csv.DictReader(open(path)) if r["status"] == "ok"]
    if not rows:
        print(f"{path}: no finished runs")
        return
    selector = next(s for s in SELECTORS if s in rows[0])
    name, onset_column, kind, ncombos = SELECTORS[selector]
    by_run = {int(r["run"]): r for r in rows}
    controls, faulty = [], []
    for r in rows:
        value = r[selector]
        (controls if value in ("0", "false", "False") else faulty).append(r)
    # False alarms in the controls.
    alarms = 0
    for r in controls:
        faces, axes = declared(r)
        alarms += len(faces) + len(axes)
    detected, right, times = 0, 0, []
    ratios_sun, ratios_ecl = [], []
    sun_fault, sun_ctrl, ecl_fault, ecl_ctrl = [], [], [], []
    missed = []
    times_by_run = {}
    for r in faulty:
        onset = float(r[onset_column])
        faces, axes = declared(r)
        if kind == "face":
            expected_faces, expected_axes = {int(r[selector])}, set()
        elif kind == "axis":
            expected_faces, expected_axes = set(), {int(r[selector])}
        else:
            expected_faces, expected_axes = set(), {1, 2, 3}
        hit = [t for k, t in faces.items() if k in expected_faces and t >= onset] + \
              [t for k, t in axes.items() if k in expected_axes and t >= onset]
        if hit:
            detected += 1
            times.append(min(hit) - onset)
            times_by_run[int(r["run"])] = min(hit) - onset
        else:
            missed.append(int(r["run"]))
        if set(faces) == expected_faces and set(axes) == expected_axes and all(
                t >= onset for t in list(faces.values()) + list(axes.values())):
            right += 1
        # The paired control: the same scene, selector 0 (runs scene*ncombos ... scene*ncombos + ncombos-1).
        scene = int(r["run"]) // ncombos
        control = next((by_run[k] for k in range(scene * ncombos, scene * ncombos + ncombos)
                        if k in by_run and by_run[k][selector] in ("0", "false", "False")), None)
        if control is None:
            continue
        for metric, out_f, out_c, ratios in (("error_sunlit.p95", sun_fault, sun_ctrl, ratios_sun),
                                             ("error_eclipse.p95", ecl_fault, ecl_ctrl, ratios_ecl)):
            f, c = float(r[metric]), float(control[metric])
            if math.isfinite(f) and math.isfinite(c) and c > 0:
                out_f.append(f)
                out_c.append(c)
                ratios.append(f / c)
    n = len(faulty)
    print(f"## {name} ({path})")
    print(f"- runs: {n} with the fault, {len(controls)} no-fault controls ({ncombos} grid values)")
    if n:
        print(f"- detected (an expected element declared after the onset): {detected}/{n} = {100.0 * detected / n:.1f} %")
        if times:
            within = sum(t <= 60.0 for t in times)
            print(f"- time to detect: median {statistics.median(times):.1f} s, p95 {percentile(times, 95):.1f} s, "
                  f"max {max(times):.1f} s; within 60 s: {within}/{n} = {100.0 * within / n:.1f} %")
        print(f"- isolation right (exactly the expected elements): {right}/{n}; wrong or incomplete: {n - right}")
        if missed:
            print(f"- missed runs: {missed}")
        if "mag.fault_stuck_mode" in faulty[0]:
            for mode in sorted({r["mag.fault_stuck_mode"] for r in faulty}):
                t = [times_by_run[int(r["run"])] for r in faulty
                     if r["mag.fault_stuck_mode"] == mode and int(r["run"]) in times_by_run]
                m = sum(1 for r in faulty if r["mag.fault_stuck_mode"] == mode)
                if t:
                    print(f"  - mode {mode}: {len(t)}/{m} detected, median {statistics.median(t):.1f} s, "
                          f"max {max(t):.1f} s, within 60 s {sum(x <= 60.0 for x in t)}/{m}")
    print(f"- false alarms in the controls: {alarms} over {len(controls)} runs")
    for label, fa, co, ra in (("sunlit", sun_fault, sun_ctrl, ratios_sun), ("eclipse", ecl_fault, ecl_ctrl, ratios_ecl)):
        if ra:
            print(f"- attitude error p95 after the fault, {label}: median over runs {statistics.median(fa):.3f} deg "
                  f"(paired no-fault {statistics.median(co):.3f} deg); ratio per pair median {statistics.median(ra):.2f}, "
                  f"p95 {percentile(ra, 95):.2f}, max {max(ra):.2f}; pairs within 1.5x: {sum(x <= 1.5 for x in ra)}/{len(ra)}")
    print()
    return alarms, len(controls)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results", nargs="+")
    parser.add_argument("--orbit", type=float, default=ORBIT, help="orbital period, s")
    parser.add_argument("--stop-time", type=float, default=8200.0, help="each run's stop time, s")
    args = parser.parse_args()
    alarms, controls = 0, 0
    for path in args.results:
        got = summarize(path)
        if got:
            alarms += got[0]
            controls += got[1]
    orbits = controls * args.stop_time / args.orbit
    print(f"All controls: {alarms} false alarms in {controls} runs = {orbits:.1f} fault-free orbits")


if __name__ == "__main__":
    main()
