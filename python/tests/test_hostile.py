"""Hostile use of the package (issue 38): what must be refused with an exception, never crash, hang or
be cut or wrapped silently."""

import gc
import os
import signal

import numpy as np
import pytest

import pvatt
from pvatt import _lib


@pytest.fixture
def chain(chain_ssd):
    system = pvatt.System(chain_ssd)
    system.set("integ.u", 1.0)  # x = 1 + t, the gain's input
    return system


def test_replacing_a_component_under_a_paused_simulation_keeps_the_callback_it_calls(chain):
    def double(t, inputs):
        return {"y": 2.0 * inputs["u"]}

    chain.replace("gain", double, sample_period=0.25)
    sim = chain.start(output_interval=0.25, outputs=["gain.y"])
    sim.advance_to(0.25)
    chain.replace("gain", None, sample_period=0)  # the system's table drops the old callback...
    chain.replace("gain", lambda t, x: {"y": -1.0}, sample_period=0.25)  # ...and another takes its place
    del double
    gc.collect()
    sim.advance_to(1.0)  # ...but this run still calls it: alive
    np.testing.assert_allclose(sim.result()["gain.y"], 2.0 * (1.0 + np.arange(5) * 0.25), atol=1e-6)
    sim.close()
    assert chain.run(output_interval=0.25, outputs=["gain.y"])["gain.y"][-1] == -1.0  # a new run: the new one


def test_a_callback_cannot_advance_or_free_its_own_simulation(chain):
    box = {"errors": [], "statuses": []}

    def component(t, inputs):
        sim = box.get("sim")
        if t >= 0.5 and sim is not None and not box.get("tried"):
            box["tried"] = True
            for action in (lambda: sim.advance_to(1.0), sim.close):
                try:
                    action()
                except pvatt.PvattError as e:
                    box["errors"].append(str(e))
            # The C API itself refuses as well (it would wait for itself, or join its own thread).
            box["statuses"].append(_lib.lib.pvatt_advance_to(sim._handle, 1.0))
        return {"y": inputs["u"]}

    chain.replace("gain", component, sample_period=0.25)
    with chain.start(output_interval=0.25) as sim:
        box["sim"] = sim
        assert sim.advance_to(1.0) == 1.0
        assert len(box["errors"]) == 2 and all("from inside its own" in e for e in box["errors"])
        assert box["statuses"] == [_lib.PVATT_WRONG_STATE]


def test_an_interrupted_advance_gives_the_partial_result(chain):
    def impatient(t, inputs):
        if t >= 0.5:
            _lib.lib.pvatt_interrupt()  # what Ctrl-C does through the library's SIGINT handler
        return {"y": inputs["u"]}

    chain.replace("gain", impatient, sample_period=0.25)
    with chain.start(output_interval=0.25, outputs=["gain.y"]) as sim:
        with pytest.raises(KeyboardInterrupt) as caught:
            sim.advance_to(1.0)
        rows = caught.value.partial_result
        assert isinstance(rows, pvatt.Result)
        assert 2 <= len(rows) < 5
        assert rows.time[0] == 0.0


def test_a_run_count_that_a_c_long_cannot_hold_is_refused(tmp_path):
    for runs in (2**64 + 1, 2**63, 0, -3):
        with pytest.raises(ValueError, match="runs must be a positive integer"):
            pvatt.run_campaign(tmp_path / "never_read.toml", runs=runs)
    with pytest.raises(TypeError):
        pvatt.run_campaign(tmp_path / "never_read.toml", runs=2.5)


def test_an_embedded_nul_is_refused_not_cut(chain):
    with pytest.raises(ValueError, match="NUL"):
        chain.set("integ.u\0junk", 2.0)
    with pytest.raises(ValueError, match="NUL"):
        chain.set("gain.sign", "minus\0plus")
    with pytest.raises(ValueError, match="NUL"):
        chain.get("gain.k\0")
    with pytest.raises(ValueError, match="NUL"):
        chain.run(outputs=["gain.y\0"])
    with chain.start(output_interval=0.25) as sim:
        with pytest.raises(ValueError, match="NUL"):
            sim["integ.u\0x"] = 3.0
    assert chain.get("integ.u") == "1.0"  # nothing was set


def test_a_refused_set_leaves_a_paused_run_able_to_advance(chain):
    with chain.start(output_interval=0.25, outputs=["integ.y"]) as sim:
        sim.advance_to(0.5)
        for name, value in (("integ.y", 5.0), ("integ.tau", 2.0), ("gain.k", 3.0), ("integ.u", float("nan"))):
            with pytest.raises(pvatt.PvattError):
                sim[name] = value
        sim.advance_to(1.0)
        assert sim["integ.y"] == pytest.approx(2.0, abs=1e-6)
