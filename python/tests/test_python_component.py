"""A Python function in place of an FMU: it equals the FMU at its samples, its exceptions come back
to the caller, and Ctrl-C stops a run cleanly."""

import os
import signal

import numpy as np
import pytest

import pvatt


@pytest.fixture
def chain(chain_ssd):
    system = pvatt.System(chain_ssd)
    system.set("integ.u", 1.0)
    return system


def test_a_python_gain_equals_the_gain_fmu_at_its_samples(chain):
    # Sampled at the output interval, the held output of y = k u equals the FMU's continuous y at
    # every output point, bit for bit (u = x(t) comes from the same integrator in both runs).
    fmu_run = chain.run(output_interval=0.05, outputs=["gain.y", "integ.y"])
    calls = []

    def gain(t, inputs):
        calls.append(t)
        return {"y": 2.0 * inputs["u"]}

    chain.replace("gain", gain, sample_period=0.05)
    python_run = chain.run(output_interval=0.05, outputs=["gain.y", "integ.y"])
    np.testing.assert_array_equal(python_run.data, fmu_run.data)
    assert calls[:3] == pytest.approx([0.0, 0.05, 0.1])


def test_a_class_with_step_and_vector_inputs(chain):
    class Gain:
        def __init__(self):
            self.seen = []

        def step(self, t, inputs):
            self.seen.append(inputs["u"])
            return {"y": -inputs["u"]}

    g = Gain()
    chain.replace("gain", g, sample_period=0.25)
    r = chain.run(output_interval=0.25, outputs=["gain.y"])
    np.testing.assert_allclose(r["gain.y"], -(1.0 + r.time), atol=1e-6)
    assert len(g.seen) >= 4


def test_the_components_exception_comes_back_as_the_cause(chain):
    def broken(t, inputs):
        if t > 0.4:
            raise ZeroDivisionError("the estimator divided by zero")
        return {"y": 0.0}

    chain.replace("gain", broken, sample_period=0.25)
    with pytest.raises(pvatt.CallbackError) as caught:
        chain.run(output_interval=0.125)
    assert isinstance(caught.value.__cause__, ZeroDivisionError)
    assert len(caught.value.partial_result) == 4  # 0 .. 0.375
    chain.replace("gain", None, sample_period=0)
    assert len(chain.run(output_interval=0.125)) == 9


def test_ctrl_c_stops_a_run_cleanly_and_the_next_run_works(chain):
    def impatient(t, inputs):
        if t >= 0.5:
            os.kill(os.getpid(), signal.SIGINT)
        return {"y": inputs["u"]}

    chain.replace("gain", impatient, sample_period=0.25)
    with pytest.raises(KeyboardInterrupt) as caught:
        chain.run(output_interval=0.125)
    assert 4 <= len(caught.value.partial_result) < 9
    chain.replace("gain", None, sample_period=0)
    assert len(chain.run(output_interval=0.125)) == 9
    # Python's own handler is back once the run is over.
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_in_a_stepped_run_exceptions_and_ctrl_c_come_back_from_advance_to(chain):
    def component(t, inputs):
        if t >= 0.5:
            raise ValueError("bad sample")
        return {"y": inputs["u"]}

    chain.replace("gain", component, sample_period=0.25)
    with chain.start(output_interval=0.25) as sim:
        sim.advance_to(0.25)
        with pytest.raises(pvatt.CallbackError) as caught:
            sim.advance_to(1.0)
        assert isinstance(caught.value.__cause__, ValueError)
        assert sim.finished

    def impatient(t, inputs):
        if t >= 0.5:
            os.kill(os.getpid(), signal.SIGINT)
        return {"y": inputs["u"]}

    # Sent from the run's own thread, the signal may be handled on the caller's thread only after the
    # run has reached the stop time: then it is raised again for Python once the call is over. Either
    # way, Ctrl-C is never lost.
    chain.replace("gain", impatient, sample_period=0.25)
    with chain.start(output_interval=0.25) as sim:
        with pytest.raises(KeyboardInterrupt):
            sim.advance_to(1.0)
