"""pvatt over the C API on a small system with a closed form (conftest.chain_ssd): runs, settings,
choices, results read in place, stepping, errors."""

import numpy as np
import pytest

import pvatt
from conftest import TEST_FMU_DIR


@pytest.fixture
def chain(chain_ssd):
    system = pvatt.System(chain_ssd)
    system.set("integ.u", 1.0)
    return system


def test_lists_components_and_variables_with_units_and_choices(chain):
    assert list(chain.components) == ["integ", "gain"]
    u = chain.variables("gain")["u"]
    assert (u.type, u.causality, u.unit) == ("Real", "input", "V")
    sign = chain.variables("gain")["sign"]
    assert sign.type == "Enumeration" and list(sign.items) == ["plus", "minus"]


def test_run_follows_the_closed_form(chain):
    chain.set("gain.k", 3)
    chain.set("gain.sign", "minus")
    assert chain.get("gain.sign") == "minus"
    r = chain.run(output_interval=0.125, outputs=["integ.y", "gain.y"])
    assert len(r) == 9
    np.testing.assert_array_equal(r.time, 0.125 * np.arange(9))
    np.testing.assert_allclose(r["integ.y"], 1.0 + r.time, atol=1e-6)
    np.testing.assert_allclose(r["gain.y"], -3.0 * (1.0 + r.time), atol=1e-6)


def test_columns_are_views_of_the_library_table_not_copies(chain):
    r = chain.run(output_interval=0.25)
    column = r["gain.y"]
    assert np.shares_memory(column, r.data)
    assert not column.flags.writeable
    del r  # the table lives as long as a view of it
    assert column.shape == (5,) and np.isfinite(column).all()


def test_to_pandas(chain):
    pd = pytest.importorskip("pandas")
    frame = chain.run(output_interval=0.5, outputs=["integ.y"]).to_pandas()
    assert isinstance(frame, pd.DataFrame)
    assert list(frame.columns) == ["integ.y"] and frame.index.name == "time"
    assert frame["integ.y"].iloc[-1] == pytest.approx(2.0, abs=1e-6)


def test_errors_carry_the_library_message(chain):
    with pytest.raises(pvatt.PvattError, match="sideways"):
        chain.set("gain.sign", "sideways")
    with pytest.raises(KeyError, match="nope"):
        chain.set("gain.nope", 1)
    with pytest.raises(pvatt.PvattError, match="stop time"):
        chain.run(stop_time=-1.0)
    with pytest.raises(pvatt.PvattError, match="/nonexistent.ssd"):
        pvatt.System("/nonexistent.ssd")


def test_stepping_pauses_reads_and_sets_and_equals_a_whole_run(chain):
    whole = chain.run(output_interval=0.1, outputs=["gain.y"])
    with chain.start(output_interval=0.1, outputs=["gain.y"]) as sim:
        assert sim.time == 0.0
        sim.advance_to(0.5)
        assert sim.time == pytest.approx(0.5)
        assert sim["integ.y"] == pytest.approx(1.5, abs=1e-6)
        assert sim["gain.sign"] == "plus"
        sim.advance_to(1.0)
        assert sim.finished
        np.testing.assert_array_equal(sim.result().data, whole.data)
    with chain.start(output_interval=0.25) as sim:
        sim.advance_to(0.5)
        sim["integ.u"] = 0.0  # the open input: x stays where it is from here on
        sim.advance_to(1.0)
        assert sim["integ.y"] == pytest.approx(1.5, abs=1e-6)
        with pytest.raises(pvatt.PvattError, match="does not go back"):
            sim.advance_to(0.25)


def test_a_lone_fmu(tmp_path):
    fmu = pvatt.Fmu(TEST_FMU_DIR / "test_gain.fmu")
    info = fmu.info()
    assert info["name"] == "test_gain"
    assert info["variables"]["y"].causality == "output" and info["variables"]["k"].start == "2"
    system = fmu.system()
    system.set("test_gain.u", 4.0)
    r = system.run(stop_time=1.0, output_interval=0.5, outputs=["test_gain.y"])
    np.testing.assert_array_equal(r["test_gain.y"], [8.0, 8.0, 8.0])


def test_system_parameters_by_name_and_from_parameter_files(tmp_path):
    """A system parameter (gain_k = 2, feeding gain.k) set by its name, from a parameter file given at
    construction and from load_parameters(); with integ.u = 1, x(1) = 2 and gain.y = k x(1) = 2 k."""
    ssd = tmp_path / "chain.ssd"
    ssd.write_text(f"""<?xml version="1.0" encoding="UTF-8"?>
<ssd:SystemStructureDescription xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription"
    xmlns:ssc="http://ssp-standard.org/SSP1/SystemStructureCommon"
    xmlns:ssv="http://ssp-standard.org/SSP1/SystemStructureParameterValues" version="1.0" name="chain">
  <ssd:System name="chain">
    <ssd:Connectors><ssd:Connector name="gain_k" kind="parameter"><ssc:Real unit="1"/></ssd:Connector></ssd:Connectors>
    <ssd:ParameterBindings><ssd:ParameterBinding><ssd:ParameterValues>
      <ssv:ParameterSet version="1.0" name="s"><ssv:Parameters>
        <ssv:Parameter name="gain_k"><ssv:Real value="2"/></ssv:Parameter>
      </ssv:Parameters></ssv:ParameterSet>
    </ssd:ParameterValues></ssd:ParameterBinding></ssd:ParameterBindings>
    <ssd:Elements>
      <ssd:Component name="integ" source="{TEST_FMU_DIR}/test_integrator.fmu"/>
      <ssd:Component name="gain" source="{TEST_FMU_DIR}/test_gain.fmu"/>
    </ssd:Elements>
    <ssd:Connections>
      <ssd:Connection startElement="integ" startConnector="y" endElement="gain" endConnector="u"/>
      <ssd:Connection startConnector="gain_k" endElement="gain" endConnector="k"/>
    </ssd:Connections>
  </ssd:System>
  <ssd:DefaultExperiment startTime="0" stopTime="1"/>
</ssd:SystemStructureDescription>
""")
    ssv = tmp_path / "minus_half.ssv"
    ssv.write_text("""<?xml version="1.0" encoding="UTF-8"?>
<ssv:ParameterSet xmlns:ssv="http://ssp-standard.org/SSP1/SystemStructureParameterValues" version="1.0" name="p">
  <ssv:Parameters>
    <ssv:Parameter name="gain_k"><ssv:Real value="-0.5"/></ssv:Parameter>
  </ssv:Parameters>
</ssv:ParameterSet>
""")

    def final(system):
        system.set("integ.u", 1.0)
        return system.run(output_interval=0.5, outputs=["gain.y"])["gain.y"][-1]

    system = pvatt.System(ssd)
    assert system.parameters == ["gain_k"]
    assert system.get("gain_k") == "2"
    assert system.expand("gain_k") == ["gain_k"]
    assert final(system) == pytest.approx(4.0, rel=1e-6)
    system.set("gain_k", 1.0)
    assert final(system) == pytest.approx(2.0, rel=1e-6)
    system.load_parameters(ssv)
    assert system.get("gain_k") == "-0.5"
    assert final(system) == pytest.approx(-1.0, rel=1e-6)
    assert final(pvatt.System(ssd, parameters=[ssv])) == pytest.approx(-1.0, rel=1e-6)
    with pytest.raises(KeyError):
        system.expand("gain_kk")
    with pytest.raises(pvatt.PvattError):
        system.load_parameters(tmp_path / "none.ssv")
