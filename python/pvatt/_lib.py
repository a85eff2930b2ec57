"""The C API (harness/capi/include/pvatt/cosim.h) through ctypes: finding libpvatt_cosim.so, the
function signatures, and turning a status into an exception carrying the library's message."""

import ctypes
import os
import pathlib
import sys

PVATT_OK = 0
PVATT_ERROR = 1
PVATT_INVALID_ARGUMENT = 2
PVATT_INTERRUPTED = 3
PVATT_CALLBACK_FAILED = 4
PVATT_BUFFER_TOO_SMALL = 5
PVATT_WRONG_STATE = 6

LIBRARY_NAME = "libpvatt_cosim.so.1"


class PvattError(RuntimeError):
    """The engine refused or failed; the message is the C API's (pvatt_last_error)."""

    def __init__(self, message, status=PVATT_ERROR):
        super().__init__(message)
        self.status = status


class CallbackError(PvattError):
    """A Python component raised; the exception it raised is this one's __cause__."""


def _candidates():
    """Where the library may be: $PVATT_LIBRARY, the build tree of the clone this package lies in
    (python/pvatt -> build/lib), then the install prefixes."""
    env = os.environ.get("PVATT_LIBRARY")
    if env:
        yield pathlib.Path(env)
    here = pathlib.Path(__file__).resolve().parent
    for build in ("build", "build-release"):
        yield here.parent.parent / build / "lib" / LIBRARY_NAME
    for prefix in (sys.prefix, "/usr/local", "/usr"):
        for libdir in ("lib", "lib64", "lib/x86_64-linux-gnu"):
            yield pathlib.Path(prefix) / libdir / LIBRARY_NAME


def find_library():
    tried = []
    for path in _candidates():
        if path.is_file():
            return path
        tried.append(str(path))
    raise ImportError(
        "pvatt: libpvatt_cosim.so not found; build it (cmake --build build --target pvatt_cosim) or set "
        "PVATT_LIBRARY. Looked at: " + ", ".join(tried)
    )


LIBRARY_PATH = find_library()
lib = ctypes.CDLL(str(LIBRARY_PATH))

c_double_p = ctypes.POINTER(ctypes.c_double)
c_char_pp = ctypes.POINTER(ctypes.c_char_p)
# The buffers arrive as plain addresses (ints): a Python component keeps numpy views of them while they
# stay where they are (one run's), instead of wrapping two pointers in new arrays at every sample.
STEP_CALLBACK = ctypes.CFUNCTYPE(
    ctypes.c_int, ctypes.c_void_p, ctypes.c_double, ctypes.c_void_p, ctypes.c_size_t, ctypes.c_void_p, ctypes.c_size_t
)


class VariableInfo(ctypes.Structure):
    _fields_ = [
        ("name", ctypes.c_char_p),
        ("type", ctypes.c_char_p),
        ("causality", ctypes.c_char_p),
        ("variability", ctypes.c_char_p),
        ("unit", ctypes.c_char_p),
        ("description", ctypes.c_char_p),
        ("start", ctypes.c_char_p),
        ("items", c_char_pp),
        ("item_count", ctypes.c_size_t),
        ("item_values", ctypes.POINTER(ctypes.c_int)),
        ("value_reference", ctypes.c_uint),
    ]


class RunOptions(ctypes.Structure):
    _fields_ = [("stop_time", ctypes.c_double), ("output_interval", ctypes.c_double), ("reference", ctypes.c_int)]


def _sig(name, restype, *argtypes):
    f = getattr(lib, name)
    f.restype = restype
    f.argtypes = list(argtypes)


_p = ctypes.c_void_p
_status = ctypes.c_int
_sig("pvatt_api_version", ctypes.c_int)
_sig("pvatt_last_error", ctypes.c_char_p)
_sig("pvatt_interrupt", None)
_sig("pvatt_catch_sigint", None, ctypes.c_int)
_sig("pvatt_system_open", _status, ctypes.c_char_p, c_char_pp, ctypes.c_size_t, ctypes.POINTER(_p))
_sig("pvatt_system_close", None, _p)
_sig("pvatt_system_default_stop_time", ctypes.c_double, _p)
_sig("pvatt_system_default_output_interval", ctypes.c_double, _p, ctypes.c_double)
_sig("pvatt_system_component_count", ctypes.c_size_t, _p)
_sig("pvatt_system_component_name", ctypes.c_char_p, _p, ctypes.c_size_t)
_sig("pvatt_system_variable_count", ctypes.c_size_t, _p, ctypes.c_size_t)
_sig("pvatt_system_variable", _status, _p, ctypes.c_size_t, ctypes.c_size_t, ctypes.POINTER(VariableInfo))
_sig("pvatt_system_set", _status, _p, ctypes.c_char_p, ctypes.c_char_p)
_sig("pvatt_system_get", _status, _p, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_size_t, ctypes.POINTER(ctypes.c_size_t))
_sig("pvatt_system_clear_settings", None, _p)
_sig("pvatt_system_parameter_count", ctypes.c_size_t, _p)
_sig("pvatt_system_parameter_name", ctypes.c_char_p, _p, ctypes.c_size_t)
_sig("pvatt_system_load_parameters", _status, _p, ctypes.c_char_p)
_sig("pvatt_system_replace", _status, _p, ctypes.c_char_p, ctypes.c_double, STEP_CALLBACK, _p)
_sig("pvatt_run_options_init", None, ctypes.POINTER(RunOptions))
_sig("pvatt_run", _status, _p, ctypes.POINTER(RunOptions), c_char_pp, ctypes.c_size_t, ctypes.POINTER(_p))
_sig("pvatt_result_rows", ctypes.c_size_t, _p)
_sig("pvatt_result_columns", ctypes.c_size_t, _p)
_sig("pvatt_result_column_name", ctypes.c_char_p, _p, ctypes.c_size_t)
_sig("pvatt_result_data", c_double_p, _p)
_sig("pvatt_result_free", None, _p)
_sig("pvatt_start", _status, _p, ctypes.POINTER(RunOptions), c_char_pp, ctypes.c_size_t, ctypes.POINTER(_p))
_sig("pvatt_advance_to", _status, _p, ctypes.c_double)
_sig("pvatt_simulation_time", ctypes.c_double, _p)
_sig("pvatt_simulation_finished", ctypes.c_int, _p)
_sig("pvatt_simulation_get_real", _status, _p, ctypes.c_char_p, c_double_p)
_sig("pvatt_simulation_set_text", _status, _p, ctypes.c_char_p, ctypes.c_char_p)
_sig(
    "pvatt_simulation_get_text",
    _status,
    _p,
    ctypes.c_char_p,
    ctypes.c_char_p,
    ctypes.c_size_t,
    ctypes.POINTER(ctypes.c_size_t),
)
_sig("pvatt_simulation_result", _status, _p, ctypes.POINTER(_p))
_sig("pvatt_simulation_free", None, _p)

class CampaignOptions(ctypes.Structure):
    _fields_ = [
        ("runs", ctypes.c_long),
        ("stop_time", ctypes.c_double),
        ("output_dir", ctypes.c_char_p),
        ("resume", ctypes.c_int),
    ]


_sig("pvatt_campaign_options_init", None, ctypes.POINTER(CampaignOptions))
_sig(
    "pvatt_campaign_run",
    _status,
    ctypes.c_char_p,
    ctypes.POINTER(CampaignOptions),
    c_char_pp,
    ctypes.c_size_t,
    c_char_pp,
    ctypes.c_size_t,
    ctypes.c_char_p,
    ctypes.c_size_t,
    ctypes.POINTER(ctypes.c_size_t),
)
_sig(
    "pvatt_campaign_aims",
    _status,
    ctypes.c_char_p,
    ctypes.c_char_p,
    ctypes.c_int,
    ctypes.c_char_p,
    ctypes.c_size_t,
    ctypes.POINTER(ctypes.c_size_t),
)

# SIGINT during a run sets the library's interrupt flag (the run stops at its next check and returns
# PVATT_INTERRUPTED, raised here as KeyboardInterrupt); Python's own handler is back after each call.
lib.pvatt_catch_sigint(1)


def check(status, callback_errors=None):
    """Raises for a failed status: KeyboardInterrupt when interrupted, the Python component's own
    exception (as the cause of a CallbackError) when it raised, PvattError otherwise."""
    if status == PVATT_OK:
        return
    message = lib.pvatt_last_error().decode("utf-8", "replace")
    if status == PVATT_INTERRUPTED:
        raise KeyboardInterrupt(message)
    if status == PVATT_CALLBACK_FAILED and callback_errors:
        raise CallbackError(message, status) from callback_errors.pop()
    if status in (PVATT_INVALID_ARGUMENT, PVATT_WRONG_STATE):
        raise PvattError(message, status)
    raise PvattError(message, status)


def text_from(function, *args, size=256):
    """The text a C call copies into a caller's buffer (the calls ending in buffer, size, needed): asked once
    with a buffer of `size` bytes, again with the size it said it needs when that was too small."""
    needed = ctypes.c_size_t()
    buffer = ctypes.create_string_buffer(size)
    status = function(*args, buffer, len(buffer), ctypes.byref(needed))
    if status == PVATT_BUFFER_TOO_SMALL:
        buffer = ctypes.create_string_buffer(needed.value)
        status = function(*args, buffer, len(buffer), None)
    check(status)
    return buffer.value.decode()


def encode(text, what="a name or value"):
    """UTF-8 bytes for a C string; a NUL inside would end the string there, so it is refused."""
    text = str(text)
    if "\0" in text:
        raise ValueError(f"{what} contains a NUL character, which a C string cannot carry: {text!r}")
    return text.encode()


def names_array(names, what="a name"):
    """A C array of UTF-8 strings (kept alive by the returned tuple's second element)."""
    encoded = [encode(n, what) for n in names]
    array = (ctypes.c_char_p * len(encoded))(*encoded)
    return array, encoded
