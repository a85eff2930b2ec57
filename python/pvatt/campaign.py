"""Monte-Carlo campaigns (harness/campaign/README.md) run in this process through the C API; the
results table (one row per run: its draws, status and metrics) read back as numpy columns, and the spec's
aims judged over it by the C++ that ends `cosim campaign` (the same counts and words)."""

import csv
import ctypes
import json
import math
import operator
import pathlib

import numpy as np

from . import _lib
from ._lib import CampaignOptions, check, encode, lib, names_array
from .system import default_fmu_dirs


class CampaignResult:
    """The table of a campaign: `table["attitude_error_p95"]` is a numpy array (numbers as float64,
    other columns as strings), one entry per run. With its spec (given by `run_campaign`, or as
    `CampaignResult("out/results.csv", spec="campaign.toml")` for a table `cosim campaign` wrote), `aims`
    and `aims_text()` say how many runs meet the spec's [[aim]] entries and which miss them: a mean or a
    median of a column can look fine while runs miss."""

    def __init__(self, path, spec=None):
        self.path = pathlib.Path(path)
        self.spec = None if spec is None else pathlib.Path(spec)
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

    def _aims(self, as_text):
        if self.spec is None:
            raise ValueError("this table was read without its spec: CampaignResult(path, spec=...) judges its aims")
        spec, table = encode(self.spec, "the spec path"), encode(self.path, "the table path")
        return _lib.text_from(lib.pvatt_campaign_aims, spec, table, as_text, size=4096)

    @property
    def aims(self):
        """The spec's aims judged per run, as `cosim campaign` ends: a dict with "finished", "failed",
        "every" (the runs that meet every aim), "missing_any" (run numbers), "aims" (per aim: "column",
        "condition" such as "error_sunlit.p95 < 1", "met", "missed", "not_judged", "missing_runs") and
        "by_category" (per kind of scene: "column", "values" with each value's "finished", "every", and per
        aim "met" / "judged"). "aims" is empty for a spec without aims."""
        return json.loads(self._aims(0))

    def aims_text(self):
        """The same as the lines `cosim campaign` ends with ("" for a spec without aims)."""
        return self._aims(1)

    def __repr__(self):
        text = f"<pvatt.CampaignResult {len(self)} runs x {len(self.names)} columns from {self.path}"
        if self.spec is not None:
            try:
                a = self.aims
                if a["aims"]:
                    text += f"; every aim met by {a['every']} of {a['finished']} finished runs"
            except Exception as e:  # a repr does not raise: it says why the aims are not judged
                text += f"; aims not judged: {e}"
        return text + ">"


def run_campaign(spec, runs=None, stop_time=None, output=None, settings=None, fmu_dirs=None, resume=False):
    """Runs the campaign of a TOML spec in this process, its runs one after the other (the spec's values
    unless given here; settings {"comp.var": value} after the spec's [set]), and returns its results
    table, the one `cosim campaign SPEC` writes (results.csv in the output folder; no summary, no figures),
    with the spec's aims judged over it (`result.aims`, `result.aims_text()`)."""
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
    return CampaignResult(buffer.value.decode(), spec=spec)
