"""A campaign run from Python gives the table `cosim campaign` gives for the same spec, and each run's
metric is the closed form of its drawn gain (y(1) = k x(1) = 2 k for the chain with u = 1); its aims are
judged as the command judges them, the counts those of the drawn gains."""

import subprocess

import numpy as np
import pytest

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

# x.final = 2 k: below 4 for k < 2; at least 2 for k >= 1
[[aim]]
column = "x.final"
below = 4.0

[[aim]]
column = "x.max"
at_least = 2.0
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


def test_python_campaign_aims_are_the_command_lines(tmp_path, chain_ssd):
    spec = write_spec(tmp_path, chain_ssd)
    table = pvatt.run_campaign(spec, output=tmp_path / "python")
    k = table["gain.k"]
    aims = table.aims
    assert [a["condition"] for a in aims["aims"]] == ["x.final < 4", "x.max >= 2"]
    # The counts from the drawn gains, not from the judge.
    assert aims["finished"] == 6 and aims["failed"] == 0
    assert aims["aims"][0]["met"] == int(np.sum(k < 2.0))
    assert aims["aims"][0]["missing_runs"] == [int(r) for r in table["run"][k >= 2.0]]
    assert aims["aims"][1]["met"] == int(np.sum(k >= 1.0))
    assert aims["every"] == int(np.sum((k < 2.0) & (k >= 1.0)))
    assert 0 < aims["every"] < 6  # the draws of seed 7 leave runs on both sides
    assert f"every aim met by {aims['every']} of 6 finished runs" in repr(table)

    cli = subprocess.run([str(COSIM), "campaign", str(spec), "--output", str(tmp_path / "cli"), "--no-figures"],
                         check=True, capture_output=True, text=True).stdout
    start = cli.index("aims, per run")
    assert table.aims_text() == cli[start:cli.index("results: ", start)]
    # A table the command wrote, judged from Python with its spec.
    written = pvatt.CampaignResult(tmp_path / "cli" / "results.csv", spec=spec)
    assert written.aims == aims


def test_aims_need_the_tables_own_spec(tmp_path, chain_ssd):
    spec = write_spec(tmp_path, chain_ssd)
    table = pvatt.run_campaign(spec, runs=2, output=tmp_path / "out")
    with pytest.raises(ValueError, match="without its spec"):
        pvatt.CampaignResult(table.path).aims
    other = tmp_path / "other.toml"
    # Another spec: one more metric and an aim on it, a column this table does not have.
    other.write_text(spec.read_text() + '\n[[metric]]\nname = "y"\nkind = "column"\ncolumn = "gain.y"\n'
                     'stats = ["max"]\n\n[[aim]]\ncolumn = "y.max"\nbelow = 1\n')
    with pytest.raises(pvatt.PvattError, match="no column 'y.max'"):
        pvatt.CampaignResult(table.path, spec=other).aims
    assert "aims not judged" in repr(pvatt.CampaignResult(table.path, spec=other))
