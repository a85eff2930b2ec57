#!/usr/bin/env python3
"""Runs FMI 3.0 FMUs through `cosim` and through fmusim (Reference-FMUs' C simulator) in every interface
each FMU offers, and prints the largest difference of every output between the two.

By hand, not in CI (the Reference FMUs and fmusim are built outside the repository, from
github.com/modelica/Reference-FMUs with FMI_VERSION=3):

    harness/engine/tests/compare_fmusim.py --cosim build/bin/cosim --fmusim /path/to/fmusim \
        /path/to/BouncingBall.fmu /path/to/Dahlquist.fmu ...

Model Exchange: cosim's CVODE against fmusim's CVODE (--solver cvode), both at --tolerance; the
difference is the two integrators' error. Co-Simulation: the FMU integrates itself, so both must agree
to rounding; with and without event mode where the FMU has it. Rows fmusim adds at events (the same
time twice) are left out: both sides are compared on the output grid.
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
import zipfile


def read_csv(path, prefix=""):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header = [h.strip('"') for h in rows[0]]
    table = {}
    for row in rows[1:]:
        t = float(row[0])
        table[round(t, 9)] = {h[len(prefix):] if h.startswith(prefix) else h: v for h, v in zip(header[1:], row[1:])}
    return header, table


def as_number(text):
    try:
        return float(text)
    except ValueError:
        return text


def compare(ours, theirs):
    """Largest difference per column over the times both have; text columns must be equal."""
    worst = {}
    for t, row in theirs.items():
        if t not in ours:
            continue
        for name, value in row.items():
            # fmusim writes an array as one column of space-separated values; cosim one column per element.
            pairs = [(name, value)] if name in ours[t] else [
                (f"{name}[{i + 1}]", v) for i, v in enumerate(value.split()) if f"{name}[{i + 1}]" in ours[t]]
            for column, v in pairs:
                a, b = as_number(ours[t][column]), as_number(v)
                if isinstance(a, float) and isinstance(b, float):
                    worst[name] = max(worst.get(name, 0.0), abs(a - b))
                elif str(a).lower() != str(b).lower():
                    worst[name] = float("inf")
    return worst


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cosim", required=True)
    ap.add_argument("--fmusim", required=True)
    ap.add_argument("--tolerance", default="1e-8")
    ap.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                    help="a start value given to both (fmusim --start-value, cosim --set)")
    ap.add_argument("fmus", nargs="+")
    args = ap.parse_args()
    failed = False
    for fmu in args.fmus:
        fmu = os.path.abspath(fmu)
        name = os.path.splitext(os.path.basename(fmu))[0]
        md = ET.fromstring(zipfile.ZipFile(fmu).read("modelDescription.xml"))
        ex = md.find("DefaultExperiment")
        stop = ex.get("stopTime", "1") if ex is not None else "1"
        step = ex.get("stepSize") if ex is not None and ex.get("stepSize") else str(float(stop) / 500)
        runs = []
        if md.find("ModelExchange") is not None:
            runs.append(("me", []))
        cs = md.find("CoSimulation")
        if cs is not None:
            runs.append(("cs", []))
            if cs.get("hasEventMode") == "true":
                runs.append(("cs", ["--event-mode-used"]))
        if not runs:
            r = subprocess.run([args.cosim, "simulate", fmu], capture_output=True, text=True)
            refused = r.returncode != 0
            failed = failed or not refused
            print(f"{name}: neither Model Exchange nor Co-Simulation; cosim "
                  f"{'refuses it: ' + r.stderr.strip() if refused else 'did not refuse it'}")
            continue
        with tempfile.TemporaryDirectory() as tmp:
            ssd = os.path.join(tmp, "one.ssd")
            with open(ssd, "w") as f:
                f.write('<?xml version="1.0" encoding="UTF-8"?>\n'
                        '<ssd:SystemStructureDescription xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription" '
                        'version="1.0" name="one"><ssd:System name="one"><ssd:Elements>'
                        f'<ssd:Component name="m" source="{fmu}"/></ssd:Elements></ssd:System>'
                        f'<ssd:DefaultExperiment startTime="0" stopTime="{stop}"/></ssd:SystemStructureDescription>\n')
            for kind, extra in runs:
                label = f"{name} {kind}{' event mode' if extra else ''}"
                theirs_csv = os.path.join(tmp, "fmusim.csv")
                ours_csv = os.path.join(tmp, "cosim.csv")
                fmusim = [args.fmusim, "--interface-type", kind, "--stop-time", stop, "--output-interval", step,
                          "--output-file", theirs_csv] + extra
                if kind == "me":
                    fmusim += ["--solver", "cvode", "--tolerance", args.tolerance]
                cosim = [args.cosim, "run", ssd, "--stop-time", stop, "--output-interval", step, "--output", ours_csv,
                         "--tolerance", args.tolerance]
                if kind == "cs":
                    cosim += ["--cs", "m", "--step", step] + ([] if extra else ["--no-event-mode"])
                for setting in args.set:
                    var, value = setting.split("=", 1)
                    if md.find(f"ModelVariables/*[@name='{var}']") is None:
                        continue
                    fmusim += ["--start-value", var, value]
                    cosim += ["--set", f"m.{setting}"]
                r1 = subprocess.run(fmusim + [fmu], capture_output=True, text=True)
                r2 = subprocess.run(cosim, capture_output=True, text=True)
                if r1.returncode or r2.returncode:
                    print(f"{label}: FAILED\n  fmusim: {r1.stderr.strip()}\n  cosim: {r2.stderr.strip()}")
                    failed = True
                    continue
                _, theirs = read_csv(theirs_csv)
                _, ours = read_csv(ours_csv, "m.")
                worst = compare(ours, theirs)
                shown = ", ".join(f"{k} {v:.3g}" for k, v in sorted(worst.items())) or "no common outputs"
                print(f"{label}: {len(theirs)} times; largest difference {shown}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
