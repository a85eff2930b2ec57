"""Memory stays flat over 1000 runs in one process: systems built and freed, results dropped, a Python
component called (its ctypes callback and arrays), a stepped run started and abandoned now and then."""

import os

import pytest

import pvatt


def rss_kib():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") // 1024


# ASan keeps freed memory in its quarantine (up to 256 MB): RSS grows by design in that build.
@pytest.mark.skipif(os.environ.get("PVATT_SANITIZED") == "1", reason="AddressSanitizer's quarantine grows RSS")
def test_rss_is_stable_over_1000_runs(chain_ssd):
    system = pvatt.System(chain_ssd)
    system.set("integ.u", 1.0)
    system.replace("gain", lambda t, inputs: {"y": 2.0 * inputs["u"]}, sample_period=0.1)

    def one(i):
        r = system.run(output_interval=0.05)
        assert len(r) == 21
        if i % 10 == 0:
            sim = system.start(output_interval=0.05)
            sim.advance_to(0.5)
            sim.close()

    for i in range(100):  # warm up: allocator pools, libraries' first use
        one(i)
    before = rss_kib()
    for i in range(1000):
        one(i)
    growth = rss_kib() - before
    # A leak of one result table (21 x 6 doubles, ~1 kB) or one FMU instance per run would grow it by
    # megabytes; allocator noise stays well under this.
    assert growth < 2048, f"RSS grew by {growth} KiB over 1000 runs"
