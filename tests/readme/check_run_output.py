#!/usr/bin/env python3
"""The output the README shows for a command is what the command prints (issue 39: the README's numbers tested).

The README shows what `cosim run harness/systems/leo_orbit.ssd` prints at its end, as an indented block after
the line "prints the integrator's statistics and then:". This runs that command from the clone and checks the
block line by line against its output:
- every README line is an output line with the same words (numbers aside), in the same order;
- every number agrees: times (s) exactly, angles, NEES/dof and coverage within 1 % or 0.005, sample counts within
  1 %. The release build (GCC) and the test build (clang with sanitizers) print the same text here (measured
  2026-12-06); the margin is for another machine's libm, whose last bits a tumbling orbit could carry into the
  third digit. A stale figure moves further: the first run of this test found the block's last line one 10 s row
  late (280 s for 270 s) and its bound 88.6° for 89.3°.
Usage: check_run_output.py CLONE COSIM
"""
import pathlib
import re
import shlex
import subprocess
import sys

MARKER = "prints the integrator's statistics and then:"
NUMBER = re.compile(r"-?\d+(?:\.\d+)?(?:e-?\d+)?")


def readme_block(text):
    """The command (the indented cosim line before the marker) and the indented block after it."""
    lines = text.split("\n")
    at = next(i for i, line in enumerate(lines) if MARKER in line)
    command = next(line.strip() for line in reversed(lines[:at]) if line.startswith("    ./build/bin/cosim"))
    block = []
    for line in lines[at + 1 :]:
        if not line.strip():
            if block:
                break
            continue
        if not line.startswith("    "):
            break
        block.append(line.strip())
    return command, block


def kind(line, match):
    """What a number in a line measures, for its tolerance: a time, a count or a measure."""
    after = line[match.end() :]
    before = line[: match.start()]
    if re.match(r" s\b", after):
        return "time"
    if before.endswith("(") and after.startswith(")"):
        return "count"
    return "measure"


def agrees(kind_, shown, got):
    if kind_ == "time":
        return shown == got
    if kind_ == "count":
        return abs(shown - got) <= 0.01 * abs(shown)
    return abs(shown - got) <= max(0.005, 0.01 * abs(shown))


def main():
    clone, cosim = pathlib.Path(sys.argv[1]), sys.argv[2]
    command, block = readme_block((clone / "README.md").read_text())
    words = shlex.split(command.split(" #")[0])
    run = subprocess.run([cosim] + words[1:], cwd=clone, capture_output=True, text=True)
    if run.returncode != 0:
        print(f"{command} exited {run.returncode}:\n{run.stderr}")
        return 1
    output = [line.strip() for line in run.stdout.split("\n") if line.strip()]
    skeleton = lambda line: NUMBER.sub("#", line)
    problems, at = [], 0
    for shown in block:
        found = next((i for i in range(at, len(output)) if skeleton(output[i]) == skeleton(shown)), None)
        if found is None:
            problems.append(f"README line not in the output (in this order): {shown}")
            continue
        at = found + 1
        got = output[found]
        for m, g in zip(NUMBER.finditer(shown), NUMBER.finditer(got)):
            k = kind(shown, m)
            if not agrees(k, float(m.group()), float(g.group())):
                problems.append(f"README shows {m.group()} ({k}) where the run prints {g.group()}:\n  README: {shown}\n"
                                f"  run:    {got}")
    for p in problems:
        print(p)
    print(f"{command}: {len(block)} README lines checked against {len(output)} output lines, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
