"""Where the tests find the build's pieces: set by CTest (harness/capi/CMakeLists.txt), or defaults
for a build in <clone>/build."""

import os
import pathlib
import textwrap

import pytest

CLONE = pathlib.Path(__file__).resolve().parents[2]
BUILD = pathlib.Path(os.environ.get("PVATT_BUILD_DIR", CLONE / "build"))
TEST_FMU_DIR = pathlib.Path(os.environ.get("PVATT_TEST_FMU_DIR", BUILD / "test_fmus"))
COSIM = pathlib.Path(os.environ.get("PVATT_COSIM", BUILD / "bin" / "cosim"))
SYSTEMS = CLONE / "harness" / "systems"
PACKED_SYSTEMS = BUILD / "systems"


@pytest.fixture
def chain_ssd(tmp_path):
    """An open input u = 1 through the test gain (y = k u, k = 2) into the test integrator
    (dx/dt = u / tau, x(0) = 1): x(t) = 1 + k t."""
    path = tmp_path / "chain.ssd"
    path.write_text(textwrap.dedent(f"""\
        <?xml version="1.0" encoding="UTF-8"?>
        <ssd:SystemStructureDescription xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription"
            xmlns:ssc="http://ssp-standard.org/SSP1/SystemStructureCommon" version="1.0" name="chain">
          <ssd:System name="chain">
            <ssd:Elements>
              <ssd:Component name="integ" source="{TEST_FMU_DIR}/test_integrator.fmu"/>
              <ssd:Component name="gain" source="{TEST_FMU_DIR}/test_gain.fmu"/>
            </ssd:Elements>
            <ssd:Connections>
              <ssd:Connection startElement="integ" startConnector="y" endElement="gain" endConnector="u"/>
            </ssd:Connections>
          </ssd:System>
          <ssd:DefaultExperiment startTime="0" stopTime="1"/>
        </ssd:SystemStructureDescription>
        """))
    return path
