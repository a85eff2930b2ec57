"""pvatt: run, step and study this project's co-simulation systems from Python.

A thin layer over the C API (libpvatt_cosim.so, harness/capi/include/pvatt/cosim.h) through ctypes:
no compiled Python extension, so the package needs nothing but Debian's python3-numpy (pandas and
matplotlib where a user wants them). See docs/python.md.
"""

from . import analysis
from ._lib import CallbackError, PvattError
from .campaign import CampaignResult, run_campaign
from .fmu import Fmu
from .result import Result
from .system import PythonComponent, Simulation, System, Variable

__all__ = ["analysis", "run_campaign", "CampaignResult", "System", "Simulation", "Result", "Variable", "PythonComponent", "Fmu", "PvattError", "CallbackError"]
__version__ = "0.1.0"
