#!/usr/bin/env python3
"""The sun vector's error against the Earth's light the computer could expect: its rms per body axis, binned by A.

From the full CSVs of robustness runs (`cosim campaign harness/campaigns/robustness.toml --run N`, 1 s rows: time,
env.irradiance, est.sun_meas[1..3], env.sun_body[1..3], env.r_eci[1..3], env.sun_eci[1..3], env.albedo_face[1..6]):
every sunlit row with a sun vector, the error est.sun_meas - env.sun_body per body axis against

    A = a(lat) (R / r)^2 max(0, cos zenith)

the light a flat plate facing the Earth gets from a Lambertian sphere lit from the zenith of the sub-satellite point
(geocentric latitude lat, the sun's zenith angle there), with the environment's zonal reflectivity a = 0.2 + 0.4
sin^2 lat (--uniform: 0.3 everywhere). What an on-board model could weigh the sun by (docs/filter.md, "The sun's
error from the albedo"); the truth's position and sun stand here for the computer's own, which differ by kilometres
and arcseconds. Also the correlation of |error| with A and with the truth's albedo on the faces over the sun's
irradiance. Needs numpy.
"""
import argparse
import csv

import numpy as np

EARTH_MEAN_RADIUS_KM = 6371.0088


def rows_of(name, uniform):
    """Per sunlit row with a sun vector: the error (3), A and the faces' albedo over the sun's irradiance."""
    out = []
    with open(name, newline="") as f:
        for r in csv.DictReader(f):
            irradiance = float(r["env.irradiance"])
            measured = np.array([float(r[f"est.sun_meas[{k}]"]) for k in (1, 2, 3)])
            if irradiance <= 0 or not np.any(measured):
                continue
            truth = np.array([float(r[f"env.sun_body[{k}]"]) for k in (1, 2, 3)])
            position = np.array([float(r[f"env.r_eci[{k}]"]) for k in (1, 2, 3)])
            if np.linalg.norm(position) > 1e5:  # m
                position = position / 1000.0
            sun = np.array([float(r[f"env.sun_eci[{k}]"]) for k in (1, 2, 3)])
            radius = np.linalg.norm(position)
            up = position / radius
            sin_lat = up[2]
            reflectivity = 0.3 if uniform else 0.2 + 0.4 * sin_lat**2
            cos_zenith = up @ sun / np.linalg.norm(sun)
            expected = reflectivity * (EARTH_MEAN_RADIUS_KM / radius) ** 2 * max(0.0, cos_zenith)
            faces = sum(float(r[f"env.albedo_face[{k}]"]) for k in range(1, 7)) / irradiance
            out.append((measured - truth, expected, faces))
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv", nargs="+")
    parser.add_argument("--uniform", action="store_true", help="reflectivity 0.3 everywhere (not zonal)")
    args = parser.parse_args()
    every = []
    print("| run file | sunlit rows | rms per axis (rad) | mean A | largest A |")
    print("| --- | --- | --- | --- | --- |")
    for name in args.csv:
        rows = rows_of(name, args.uniform)
        if not rows:
            continue
        every += rows
        e = np.array([x[0] for x in rows])
        a = np.array([x[1] for x in rows])
        rms = ", ".join(f"{v:.3f}" for v in np.sqrt((e**2).mean(axis=0)))
        print(f"| {name} | {len(rows)} | {rms} | {a.mean():.3f} | {a.max():.3f} |")
    e = np.array([x[0] for x in every])
    a = np.array([x[1] for x in every])
    faces = np.array([x[2] for x in every])
    size = np.linalg.norm(e, axis=1)
    print(f"\ncorrelation of |error| with A {np.corrcoef(size, a)[0, 1]:.2f}, with the faces' albedo "
          f"{np.corrcoef(size, faces)[0, 1]:.2f}\n")
    print("| A | rows | rms per axis (rad) | rms, the three axes |")
    print("| --- | --- | --- | --- |")
    edges = [0.0, 0.05, 0.10, 0.15, 0.20, 0.25, 0.30, 0.35, 0.50]
    for lo, hi in zip(edges[:-1], edges[1:]):
        inside = (a >= lo) & (a < hi)
        if inside.sum() < 50:
            continue
        rms = np.sqrt((e[inside] ** 2).mean(axis=0))
        print(f"| {lo:.2f}-{hi:.2f} | {inside.sum()} | {', '.join(f'{v:.3f}' for v in rms)} | "
              f"{np.sqrt((e[inside] ** 2).sum(axis=1).mean() / 3):.3f} |")


if __name__ == "__main__":
    main()
