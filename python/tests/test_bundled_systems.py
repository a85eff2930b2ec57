"""The Python run of each bundled system equals the command line's CSV bit for bit (the same engine,
the same rows; the CSV's numbers are written to round-trip). The hardware-in-the-loop systems need a
board and are left out."""

import subprocess

import numpy as np
import pytest

import pvatt
from conftest import COSIM, PACKED_SYSTEMS, SYSTEMS

CASES = [
    ("seed_spin.ssd", 1.0, [], []),
    ("seed_spin.ssd", 0.5, ["est.sun_method=cones", "plant.fidelity=averaged"], []),
    ("leo_orbit.ssd", 120.0, [], []),
    ("seed_spin.ssp", 0.5, [], ["plant.v_bus", "est.q_est", "env.q_true"]),
]


def read_csv(path):
    with open(path) as f:
        header = f.readline().strip().split(",")
    return header, np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)


@pytest.mark.parametrize("name,stop,settings,outputs", CASES)
def test_python_run_equals_the_command_line_csv(tmp_path, name, stop, settings, outputs):
    path = (PACKED_SYSTEMS if name.endswith(".ssp") else SYSTEMS) / name
    if not path.exists():
        pytest.skip(f"{path} not built")
    csv = tmp_path / "run.csv"
    command = [str(COSIM), "run", str(path), "--stop-time", str(stop), "--output", str(csv)]
    for s in settings:
        command += ["--set", s]
    system = pvatt.System(path)
    names = [n for o in outputs for n in system.expand(o)]
    if names:
        command += ["--columns", ",".join(names)]
    subprocess.run(command, check=True, capture_output=True)
    header, rows = read_csv(csv)

    for s in settings:
        variable, _, value = s.partition("=")
        system.set(variable, value)
    result = system.run(stop_time=stop, outputs=outputs or None)
    assert result.names == header
    assert result.data.shape == rows.shape
    np.testing.assert_array_equal(result.data, rows)
