"""What a run reached, with the same measures as the command line (issue 40).

The numbers come from the C++ that `cosim run` and `cosim plot` use (harness/systems/analysis,
run_measures.hpp), called through the C API (pvatt_result_measures): there is no second definition in
Python that could drift from theirs.

>>> r = pvatt.System("harness/systems/leo_orbit.ssd").run()
>>> m = pvatt.analysis.measures(r)
>>> m["estimates"][0]["overall"]["sunlit"]["p95"]      # the filter's sunlit p95 (deg)
>>> print(pvatt.analysis.report(r))                     # the lines `cosim run` ends with
"""

import ctypes
import json
import math

from . import _lib
from ._lib import lib

_lib._sig(
    "pvatt_result_measures",
    _lib._status,
    _lib._p,
    ctypes.c_double,
    ctypes.c_int,
    ctypes.c_char_p,
    ctypes.c_size_t,
    ctypes.POINTER(ctypes.c_size_t),
)

#: chi2(3)'s 99 % point: a consistent filter's normalized error dtheta' inv(P) dtheta is below it in 99 % of samples.
CHI2_3DOF_99 = 11.344866730144373


def _call(result, converged_after, as_text):
    after = math.nan if converged_after is None else float(converged_after)
    return _lib.text_from(lib.pvatt_result_measures, result._owner.handle, after, as_text, size=4096)


def measures(result, converged_after=None):
    """A dict: per estimate (filter q_filt, single-frame q_est) its error (deg) overall, sunlit and in
    eclipse (samples, median, p95), over the whole run ("overall") and after convergence ("converged",
    from `converged_after` s, default the filter valid with the magnetometer calibration applied), the
    filter's "consistency" (NEES/dof, chi2(3) 99 % coverage in %), its first valid time, why it was not
    valid before ("not_valid_reason"), and the faults the on-board computer declared. The result needs
    the columns cosim's measures read (run with every output, or name env.q_true, est.q_filt, ...)."""
    return json.loads(_call(result, converged_after, 0))


def report(result, converged_after=None):
    """The same as text: the lines `cosim run` prints at the end of a system that declares its measures."""
    return _call(result, converged_after, 1)
