"""Monte-Carlo campaigns (harness/campaign/README.md) run in this process through the C API; the
results table (one row per run: its draws, status and metrics) read back as numpy columns."""

import csv
import ctypes
import math
import operator
import pathlib

import numpy as np

from ._lib import CampaignOptions, check, encode, lib, names_array
from .system import default_fmu_dirs


class CampaignResult:
    """The table of a campaign: `table["attitude_error_p95"]` is a numpy array (numbers as float64,
    other columns as strings), one entry per run."""

    def __init__(self, path):
        self.path = pathlib.Path(path)
        with open(self.path, newline="") as f:
            rows = list(csv.reader(f))
        self.names = rows[0]
        self.columns = {}
        for i, name in enumerate(self.names):
            cells = [r[i] for r in rows[1:]]
            try:
                self.columns[name] = np.array([float(c) if c != "" else math.nan for c in cells])
            except ValueError:
                self.columns[name] = np.array(cells)

    def __getitem__(self, name):
        return self.columns[name]

    def __len__(self):
        return len(next(iter(self.columns.values()))) if self.columns else 0

    def to_pandas(self):
        import pandas as pd

        return pd.read_csv(self.path)

    def __repr__(self):
        return f"<pvatt.CampaignResult {len(self)} runs x {len(self.names)} columns from {self.path}>"


def run_campaign(spec, runs=None, stop_time=None, output=None, settings=None, fmu_dirs=None, resume=False):
    """Runs the campaign of a TOML spec in this process, its runs one after the other (the spec's values
    unless given here; settings {"comp.var": value} after the spec's [set]), and returns its results
    table, the one `cosim campaign SPEC` writes (results.csv in the output folder; no summary, no figures)."""
    o = CampaignOptions()
    lib.pvatt_campaign_options_init(ctypes.byref(o))
    if runs is not None:
        # A C long: a larger number would wrap (2**64 + 1 -> 1), 0 or less would mean "the spec's".
        n = operator.index(runs)
        if not 1 <= n <= 2**63 - 1:
            raise ValueError(f"runs must be a positive integer that fits a C long (at most 2**63 - 1), got {runs}")
        o.runs = n
    if stop_time is not None:
        o.stop_time = float(stop_time)
    if output is not None:
        o.output_dir = encode(output, "the output folder")
    o.resume = int(bool(resume))
    texts = [f"{k}={v}" for k, v in (settings or {}).items()]
    dirs = [str(d) for d in (default_fmu_dirs() if fmu_dirs is None else fmu_dirs)]
    settings_array, keep1 = names_array(texts, "a setting")
    dirs_array, keep2 = names_array(dirs, "an FMU folder")
    buffer = ctypes.create_string_buffer(4096)
    needed = ctypes.c_size_t()
    check(lib.pvatt_campaign_run(encode(spec, "the spec path"), ctypes.byref(o), settings_array, len(texts), dirs_array,
                                 len(dirs), buffer, len(buffer), ctypes.byref(needed)))
    return CampaignResult(buffer.value.decode())
