"""A campaign run from Python gives the table `cosim campaign` gives for the same spec, and each run's
metric is the closed form of its drawn gain (y(1) = k x(1) = 2 k for the chain with u = 1)."""

import subprocess

import numpy as np

import pvatt
from conftest import COSIM


def write_spec(folder, ssd):
    spec = folder / "gain.toml"
    spec.write_text(f"""system = "{ssd}"
stop_time = 1.0
output_interval = 0.25
runs = 6
seed = 7
output = "unused"

[set]
"integ.u" = 1.0

[[draw]]
kind = "uniform"
target = "gain.k"
min = 0.5
max = 4.0

[[metric]]
name = "x"
kind = "column"
column = "gain.y"
stats = ["final", "max"]
""")
    return spec


def test_python_campaign_table_equals_the_command_line(tmp_path, chain_ssd):
    spec = write_spec(tmp_path, chain_ssd)
    table = pvatt.run_campaign(spec, output=tmp_path / "python")
    assert len(table) == 6 and list(table["status"]) == ["ok"] * 6
    np.testing.assert_allclose(table["x.final"], 2.0 * table["gain.k"], atol=1e-6)

    subprocess.run([str(COSIM), "campaign", str(spec), "--output", str(tmp_path / "cli"), "--no-figures"],
                   check=True, capture_output=True)
    cli = pvatt.CampaignResult(tmp_path / "cli" / "results.csv")
    assert cli.names == table.names
    for name in cli.names:
        if name != "wall_time":
            np.testing.assert_array_equal(cli[name], table[name], err_msg=name)
