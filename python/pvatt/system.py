"""Systems, stepped simulations and Python components over the C API."""

import ctypes
import difflib
import math
import os
import pathlib
import re

import numpy as np

from . import _lib
from ._lib import RunOptions, VariableInfo, check, encode, lib, names_array
from .result import Result

_ELEMENT = re.compile(r"^(.*)\[(\d+)\]$")

_lib._sig("pvatt_system_replace_current_inputs", _lib._status, _lib._p, ctypes.c_char_p, ctypes.c_int)


def default_fmu_dirs():
    """The FMU folders a bundled system's FMUs are looked for in: $PVATT_FMU_DIR, else the fmus/
    folder beside the library's lib/ (the build tree's build/fmus, or <prefix>/fmus)."""
    env = os.environ.get("PVATT_FMU_DIR")
    dirs = [pathlib.Path(p) for p in env.split(os.pathsep)] if env else []
    beside = _lib.LIBRARY_PATH.resolve().parent.parent / "fmus"
    if beside.is_dir():
        dirs.append(beside)
    return dirs


class Variable:
    """One variable of a component, as its model description gives it."""

    __slots__ = ("name", "type", "causality", "variability", "unit", "description", "start", "items")

    def __init__(self, info):
        self.name = info.name.decode()
        self.type = info.type.decode()
        self.causality = info.causality.decode()
        self.variability = info.variability.decode()
        self.unit = info.unit.decode()
        self.description = info.description.decode()
        self.start = info.start.decode()
        self.items = {info.items[i].decode(): info.item_values[i] for i in range(info.item_count)}

    def __repr__(self):
        unit = f" [{self.unit}]" if self.unit else ""
        return f"<{self.causality} {self.type} {self.name}{unit}>"


def _did_you_mean(name, known):
    """" (did you mean 'a' or 'b'?)" for the closest names (a vector's elements offered by its base name), or "".
    Python's difflib, not the C++ name_hint: only the wording of the hint, not a measure, is at stake."""
    candidates = set(known)
    candidates.update(m.group(1) for m in map(_ELEMENT.match, known) if m)
    close = difflib.get_close_matches(name, sorted(candidates), n=3, cutoff=0.75)
    return f" (did you mean {' or '.join(repr(c) for c in close)}?)" if close else ""


def _text(value):
    """A value as the C API's text: numbers round-trip, Booleans true/false, choices by name."""
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        return repr(float(value))
    return str(value)


def _options(stop_time, output_interval, reference):
    o = RunOptions()
    lib.pvatt_run_options_init(ctypes.byref(o))
    if stop_time is not None:
        o.stop_time = float(stop_time)
    if output_interval is not None:
        o.output_interval = float(output_interval)
    o.reference = 1 if reference else 0
    return o


class System:
    """A system (.ssd, .ssp) or a lone FMU, loaded and checked.

    >>> s = System("harness/systems/seed_spin.ssd")
    >>> s.set("est.sun_method", "cones")
    >>> r = s.run(stop_time=2.0, outputs=["plant.v_bus", "est.q_est"])

    A system's own parameters (`parameters`, e.g. "epoch_month", "tle_elements[2]") are set by their
    names; parameter sets (.ssv) load with load_parameters() or System(path, parameters=[...]).
    """

    def __init__(self, path, fmu_dirs=None, parameters=None):
        self.path = pathlib.Path(path)
        dirs = [str(d) for d in (default_fmu_dirs() if fmu_dirs is None else fmu_dirs)]
        array, keep = names_array(dirs, "an FMU folder")
        handle = ctypes.c_void_p()
        check(lib.pvatt_system_open(encode(self.path, "the path"), array, len(dirs), ctypes.byref(handle)))
        self._handle = handle
        # component -> (ctypes callback, PythonComponent). A run or a Simulation keeps its own copy of this
        # table: a replace() while a Simulation of the old callbacks is paused must not free the one it calls.
        self._callbacks = {}
        self._callback_errors = []
        self.components = {}
        for c in range(lib.pvatt_system_component_count(handle)):
            name = lib.pvatt_system_component_name(handle, c).decode()
            variables = {}
            for v in range(lib.pvatt_system_variable_count(handle, c)):
                info = VariableInfo()
                check(lib.pvatt_system_variable(handle, c, v, ctypes.byref(info)))
                variables[info.name.decode()] = Variable(info)
            self.components[name] = variables
        # The system's own parameters (system-level parameter connectors), by name.
        self.parameters = [
            lib.pvatt_system_parameter_name(handle, i).decode() for i in range(lib.pvatt_system_parameter_count(handle))
        ]
        for file in parameters or []:
            self.load_parameters(file)

    def load_parameters(self, path):
        """Every value of an SSP parameter set (.ssv: system parameters and comp.var), as set() in the
        file's order; later sets and files win. A malformed file is refused with its line and name."""
        check(lib.pvatt_system_load_parameters(self._handle, str(path).encode()))

    def close(self):
        if getattr(self, "_handle", None):
            lib.pvatt_system_close(self._handle)
            self._handle = None

    def __del__(self):
        self.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    @property
    def default_stop_time(self):
        t = lib.pvatt_system_default_stop_time(self._handle)
        return None if math.isnan(t) else t

    def variables(self, component):
        return self.components[component]

    def expand(self, name):
        """'est.q_est' -> ['est.q_est[1]', ..., 'est.q_est[4]'] for a vector; a scalar as it is. A system
        parameter by its name ('inertia' -> ['inertia[1]', ..., 'inertia[9]'])."""
        encode(name, "the name")  # a NUL is refused as such, not reported as an unknown name
        if "." not in name:
            if name in self.parameters:
                return [name]
            elements = []
            while f"{name}[{len(elements) + 1}]" in self.parameters:
                elements.append(f"{name}[{len(elements) + 1}]")
            if not elements:
                raise KeyError(f"no system parameter named '{name}'{_did_you_mean(name, self.parameters)} "
                               f"(system parameters: {', '.join(self.parameters)})")
            return elements
        component, _, variable = name.partition(".")
        variables = self.components.get(component)
        if variables is None:
            raise KeyError(f"no component named '{component}'{_did_you_mean(component, self.components)}")
        if variable in variables:
            return [name]
        elements = []
        while f"{variable}[{len(elements) + 1}]" in variables:
            elements.append(f"{component}.{variable}[{len(elements) + 1}]")
        if not elements:
            raise KeyError(f"no variable '{variable}' in component '{component}'{_did_you_mean(variable, variables)}")
        return elements

    def set(self, name, value):
        """A value for every later run (as `cosim run --set`): numbers, Booleans, choices by name;
        a vector name takes a sequence."""
        names = self.expand(name)
        values = list(value) if len(names) > 1 else [value]
        if len(values) != len(names):
            raise ValueError(f"{name} has {len(names)} elements, got {len(values)} values")
        for n, v in zip(names, values):
            check(lib.pvatt_system_set(self._handle, encode(n, "the name"), encode(_text(v), "the value")))

    def get(self, name):
        """The value set, else the description's or the FMU's start value, as text."""
        return _lib.text_from(lib.pvatt_system_get, self._handle, encode(name, "the name"))

    def clear_settings(self):
        lib.pvatt_system_clear_settings(self._handle)

    def replace(self, component, step, sample_period, current_inputs=False):
        """Runs `step` in place of the component's FMU, sampled every `sample_period` seconds (see
        PythonComponent). `step=None` puts the FMU back.

        At an instant where other components sample as well, `step` is called once, with its inputs as
        they were just before the instant (a sampled source's previous output; docs/python.md, "Order at
        a shared instant"). `current_inputs=True` calls it again at that instant whenever its inputs
        changed after its call (another component sampled and changed them), so that its last call sees
        the instant's final inputs: a sensor that must follow a command issued at this very instant."""
        if step is None:
            check(lib.pvatt_system_replace(self._handle, encode(component, "the component"), 0.0, _lib.STEP_CALLBACK(),
                                           None))
            self._callbacks.pop(component, None)
            return
        python_component = PythonComponent(self.components[component], step, self._callback_errors)
        callback = _lib.STEP_CALLBACK(python_component)
        check(lib.pvatt_system_replace(self._handle, encode(component, "the component"), float(sample_period), callback,
                                       None))
        self._callbacks[component] = (callback, python_component)
        if current_inputs:
            check(lib.pvatt_system_replace_current_inputs(self._handle, component.encode(), 1))

    def _columns(self, outputs):
        if outputs is None:
            return None, [], 0
        names = [n for o in outputs for n in self.expand(o)]
        array, keep = names_array(names, "an output name")
        return array, keep, len(names)

    def run(self, stop_time=None, output_interval=None, outputs=None, reference=False):
        """Runs from the start to stop_time (default: the description's) and returns a Result with
        the rows `cosim run` would write (every output of every component unless `outputs` names
        columns; a vector by its base name). Ctrl-C stops it: KeyboardInterrupt."""
        options = _options(stop_time, output_interval, reference)
        array, keep, n = self._columns(outputs)
        handle = ctypes.c_void_p()
        in_use = dict(self._callbacks)  # alive for the whole run, whatever a callback replaces meanwhile
        status = lib.pvatt_run(self._handle, ctypes.byref(options), array, n, ctypes.byref(handle))
        del in_use
        result = Result(handle) if handle else None
        try:
            check(status, self._callback_errors)
        except BaseException as e:
            e.partial_result = result  # the rows computed before it stopped
            raise
        return result

    def start(self, stop_time=None, output_interval=None, outputs=None):
        """A simulation paused at its start; advance_to() moves it on to any output point."""
        return Simulation(self, stop_time, output_interval, outputs)


class Simulation:
    """A run that pauses: sim.advance_to(10.0); sim["plant.v_bus"]; sim["plant.load_resistance"] = 30."""

    def __init__(self, system, stop_time, output_interval, outputs):
        self.system = system
        self._callbacks = dict(system._callbacks)  # the callbacks this run calls, alive as long as it is
        self._advancing = False
        options = _options(stop_time, output_interval, False)
        array, keep, n = system._columns(outputs)
        handle = ctypes.c_void_p()
        check(lib.pvatt_start(system._handle, ctypes.byref(options), array, n, ctypes.byref(handle)), system._callback_errors)
        self._handle = handle

    def close(self):
        if getattr(self, "_handle", None):
            if self._advancing:
                raise _lib.PvattError("Simulation.close() from inside its own advance_to (a callback of this run): "
                                      "close it after advance_to has returned", _lib.PVATT_WRONG_STATE)
            lib.pvatt_simulation_free(self._handle)
            self._handle = None

    def __del__(self):
        if not getattr(self, "_advancing", False):
            self.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    @property
    def time(self):
        return lib.pvatt_simulation_time(self._handle)

    @property
    def finished(self):
        return bool(lib.pvatt_simulation_finished(self._handle))

    def advance_to(self, t):
        """Runs on to the output point nearest t and pauses there. Ctrl-C or an error stops it: the
        exception's `partial_result` holds the rows up to where it stopped."""
        if self._advancing:
            raise _lib.PvattError("advance_to() from inside its own advance_to (a callback of this run)",
                                  _lib.PVATT_WRONG_STATE)
        self._advancing = True
        try:
            status = lib.pvatt_advance_to(self._handle, float(t))
            self._advancing = False
            check(status, self.system._callback_errors)
        except BaseException as e:  # also a Ctrl-C that Python's handler raises as the call returns
            self._advancing = False
            if getattr(e, "partial_result", None) is None:
                try:
                    e.partial_result = self.result()
                except _lib.PvattError:
                    e.partial_result = None
            raise
        return self.time

    def _get(self, name):
        component, _, variable = name.partition(".")
        if self.system.components[component][variable].type in ("String", "Enumeration"):
            return _lib.text_from(lib.pvatt_simulation_get_text, self._handle, encode(name, "the name"))
        x = ctypes.c_double()
        check(lib.pvatt_simulation_get_real(self._handle, encode(name, "the name"), ctypes.byref(x)))
        return x.value

    def __getitem__(self, name):
        """A value at the paused instant: a float (a vector as an array; a String, or a choice by its
        name, as text)."""
        names = self.system.expand(name)
        if len(names) == 1 and names[0] == name:
            return self._get(name)
        return np.array([self._get(n) for n in names])

    def __setitem__(self, name, value):
        names = self.system.expand(name)
        values = list(value) if len(names) > 1 else [value]
        if len(values) != len(names):
            raise ValueError(f"{name} has {len(names)} elements, got {len(values)} values")
        for n, v in zip(names, values):
            check(lib.pvatt_simulation_set_text(self._handle, encode(n, "the name"), encode(_text(v), "the value")))

    def result(self):
        """The rows sampled so far (a copy of them: the run goes on)."""
        handle = ctypes.c_void_p()
        check(lib.pvatt_simulation_result(self._handle, ctypes.byref(handle)))
        return Result(handle)


class PythonComponent:
    """The callback behind System.replace: calls `step(t, inputs) -> outputs` (a callable, or an object
    with a step method) at each sample. `inputs` maps each input's name to its value (a vector's
    elements gathered under its base name as a numpy array: inputs["i_face"]); `outputs` is a mapping
    of output names (or vector base names) to values; outputs not returned keep their last value."""

    def __init__(self, variables, step, errors):
        self.step = step.step if hasattr(step, "step") else step
        self.errors = errors
        inputs = [n for n, v in variables.items() if v.causality == "input"]
        outputs = [n for n, v in variables.items() if v.causality == "output"]
        self.input_groups = self._groups(inputs)
        self._buffers = None
        self.output_slots = {}
        for name, index in self._groups(outputs):
            self.output_slots[name] = index

    @staticmethod
    def _groups(names):
        """(base name, index or slice) per scalar or vector, in order."""
        groups, i = [], 0
        while i < len(names):
            m = _ELEMENT.match(names[i])
            if m and m.group(2) == "1":
                n = 1
                while i + n < len(names) and names[i + n] == f"{m.group(1)}[{n + 1}]":
                    n += 1
                groups.append((m.group(1), slice(i, i + n)))
                i += n
            else:
                groups.append((names[i], i))
                i += 1
        return groups

    @staticmethod
    def _view(address, n):
        return np.frombuffer((ctypes.c_double * n).from_address(address), dtype=np.float64) if n else np.empty(0)

    def __call__(self, user, t, inputs, n_in, outputs, n_out):
        try:
            if self._buffers != (inputs, n_in, outputs, n_out):  # a new run: its buffers are elsewhere
                self._buffers = (inputs, n_in, outputs, n_out)
                self._x, self._y = self._view(inputs, n_in), self._view(outputs, n_out)
            x, y = self._x, self._y
            given = {name: (x[index].copy() if isinstance(index, slice) else float(x[index]))
                     for name, index in self.input_groups}
            answer = self.step(t, given)
            if answer:
                for name, value in answer.items():
                    y[self.output_slots[name]] = value
            return 0
        except BaseException as e:  # a Python exception must not cross ctypes: the run stops and re-raises it
            self.errors.append(e)
            return 1
