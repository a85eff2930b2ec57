"""A run's sampled columns as numpy arrays read in place from the C library's table (no copy):
`result["plant.v_bus"]` is a view of one column, `result["est.q_est"]` of the four adjacent columns
q_est[1..4] as an (n, 4) array."""

import ctypes
import difflib
import re

import numpy as np

from ._lib import lib

_ELEMENT = re.compile(r"^(.*)\[(\d+)\]$")


class _Table:
    """Owns one pvatt_result; freed when the last array viewing it is gone."""

    def __init__(self, handle):
        self.handle = handle

    def __del__(self):
        lib.pvatt_result_free(self.handle)


class Result:
    def __init__(self, handle):
        table = _Table(handle)
        self._owner = table  # the C table, for pvatt.analysis (which reads it through the C API)
        rows = lib.pvatt_result_rows(handle)
        columns = lib.pvatt_result_columns(handle)
        self.names = [lib.pvatt_result_column_name(handle, i).decode() for i in range(columns)]
        if rows * columns:
            buffer = (ctypes.c_double * (rows * columns)).from_address(
                ctypes.addressof(lib.pvatt_result_data(handle).contents)
            )
            buffer._table = table  # the memory lives as long as any view of it
            self.data = np.frombuffer(buffer, dtype=np.float64).reshape(rows, columns)
        else:
            self.data = np.empty((0, columns))
            self._table = table
        self.data.flags.writeable = False
        self._index = {name: i for i, name in enumerate(self.names)}
        # Vectors: "est.q_est" -> the first column of q_est[1..n] when they are adjacent and in order.
        self._vectors = {}
        for i, name in enumerate(self.names):
            m = _ELEMENT.match(name)
            if m and m.group(2) == "1":
                n = 1
                while i + n < len(self.names) and self.names[i + n] == f"{m.group(1)}[{n + 1}]":
                    n += 1
                self._vectors[m.group(1)] = (i, n)

    @property
    def time(self):
        return self.data[:, 0]

    def __len__(self):
        return self.data.shape[0]

    def __contains__(self, name):
        return name in self._index or name in self._vectors

    def __getitem__(self, name):
        """A column (n,) or a vector's columns (n, k), as read-only views."""
        if name in self._index:
            return self.data[:, self._index[name]]
        if name in self._vectors:
            first, n = self._vectors[name]
            return self.data[:, first : first + n]
        close = difflib.get_close_matches(name, list(self._index) + list(self._vectors), n=3, cutoff=0.75)
        hint = f" (did you mean {' or '.join(repr(c) for c in close)}?)" if close else ""
        raise KeyError(f"no column '{name}' in the result{hint} (columns: {', '.join(self.names[:8])}, ...)")

    def columns(self):
        """The column names, vectors by their base name, time first."""
        seen, out = set(), []
        for name in self.names:
            m = _ELEMENT.match(name)
            base = m.group(1) if m and m.group(1) in self._vectors else name
            if base not in seen:
                seen.add(base)
                out.append(base)
        return out

    def to_pandas(self):
        """A pandas DataFrame indexed by time, one column per scalar (a copy: pandas owns its data)."""
        import pandas as pd

        return pd.DataFrame(self.data[:, 1:], index=pd.Index(self.time, name="time"), columns=self.names[1:])

    def __repr__(self):
        return f"<pvatt.Result {len(self)} rows x {len(self.names)} columns>"
