// System parameters through the command line (issue 37): `cosim run --set NAME=VALUE` without a component
// sets a system parameter (a misspelt one gets the closest names), `--parameters FILE.ssv` reads a parameter
// set (later files win, --set last), a component parameter set directly wins over the system parameter for
// that component only (said on stderr), and `cosim info` lists the system parameters with their values,
// units and the component parameters each feeds.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/cosim_error.hpp"
#include "engine/csv_table.hpp"
#include "info_command.hpp"
#include "run_command.hpp"

namespace cosim {
namespace {

namespace fs = std::filesystem;
const fs::path fmu_dir = COSIM_TEST_FMU_DIR;

struct Scratch {
    fs::path root;
    Scratch() {
        std::string pattern = (fs::temp_directory_path() / "cosim_sysparam_XXXXXX").string();
        root = ::mkdtemp(pattern.data());
    }
    ~Scratch() { fs::remove_all(root); }
    fs::path write(const std::string& name, const std::string& text) const {
        std::ofstream(root / name) << text;
        return root / name;
    }
    // Two gains in series, a.u = 1: y of b is k_a k_b; the system parameter gain_k (3) feeds both k.
    fs::path ssd() const {
        return write("gains.ssd", R"(<?xml version="1.0" encoding="UTF-8"?>
<ssd:SystemStructureDescription xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription"
    xmlns:ssc="http://ssp-standard.org/SSP1/SystemStructureCommon"
    xmlns:ssv="http://ssp-standard.org/SSP1/SystemStructureParameterValues" version="1.0" name="gains">
  <ssd:System name="gains">
    <ssd:Connectors><ssd:Connector name="gain_k" kind="parameter"><ssc:Real unit="1"/></ssd:Connector></ssd:Connectors>
    <ssd:ParameterBindings><ssd:ParameterBinding><ssd:ParameterValues>
      <ssv:ParameterSet version="1.0" name="s"><ssv:Parameters>
        <ssv:Parameter name="gain_k"><ssv:Real unit="1" value="3"/></ssv:Parameter>
      </ssv:Parameters></ssv:ParameterSet>
    </ssd:ParameterValues></ssd:ParameterBinding></ssd:ParameterBindings>
    <ssd:Elements>
      <ssd:Component name="a" source="test_gain.fmu"/><ssd:Component name="b" source="test_gain.fmu"/>
    </ssd:Elements>
    <ssd:Connections>
      <ssd:Connection startElement="a" startConnector="y" endElement="b" endConnector="u"/>
      <ssd:Connection startConnector="gain_k" endElement="a" endConnector="k"/>
      <ssd:Connection startConnector="gain_k" endElement="b" endConnector="k"/>
    </ssd:Connections>
  </ssd:System>
  <ssd:DefaultExperiment startTime="0" stopTime="1"/>
</ssd:SystemStructureDescription>
)");
    }
    fs::path ssv(const std::string& name, const std::string& parameters) const {
        return write(name, R"(<?xml version="1.0" encoding="UTF-8"?>
<ssv:ParameterSet xmlns:ssv="http://ssp-standard.org/SSP1/SystemStructureParameterValues" version="1.0" name="p">
  <ssv:Parameters>
)" + parameters + R"(
  </ssv:Parameters>
</ssv:ParameterSet>
)");
    }
};

// b.y at the end of a short run with these settings and parameter files.
double final_y(const Scratch& s, std::vector<std::string> settings, std::vector<fs::path> files = {}) {
    RunOptions o;
    o.ssd = s.ssd();
    o.system.fmu_dirs = {fmu_dir};
    o.system.settings = std::move(settings);
    o.system.parameter_files = std::move(files);
    o.progress = false;
    o.stop_time = 0.5;
    o.output_interval = 0.5;
    o.csv = s.root / "out.csv";
    std::ostringstream report;
    run_system(o, report);
    const CsvTable t = read_csv(*o.csv);
    return t.columns[*t.find("b.y")].back();
}

TEST(SystemParameters, SetWithoutAComponentSetsTheSystemParameter) {
    Scratch s;
    EXPECT_EQ(final_y(s, {}), 9.0);
    EXPECT_EQ(final_y(s, {"gain_k=2"}), 4.0);
    EXPECT_EQ(final_y(s, {"gain_k=2", "a.k=5"}), 10.0);  // the direct set wins for a only
}

TEST(SystemParameters, AMisspeltSystemParameterGetsTheClosestName) {
    Scratch s;
    try {
        final_y(s, {"gain_kk=2"});
        FAIL() << "a misspelt system parameter was taken";
    } catch (const SettingError& e) {
        EXPECT_NE(std::string(e.what()).find("'gain_kk' is no system parameter of gains.ssd (did you mean 'gain_k'?)"),
                  std::string::npos)
            << e.what();
    }
}

TEST(SystemParameters, ParameterFilesInOrderThenSet) {
    Scratch s;
    const auto two = s.ssv("two.ssv", R"(<ssv:Parameter name="gain_k"><ssv:Real value="2"/></ssv:Parameter>)");
    const auto five = s.ssv("five.ssv", R"(<ssv:Parameter name="gain_k"><ssv:Real value="5"/></ssv:Parameter>
<ssv:Parameter name="b.k"><ssv:Real value="1"/></ssv:Parameter>)");
    EXPECT_EQ(final_y(s, {}, {two}), 4.0);
    EXPECT_EQ(final_y(s, {}, {two, five}), 5.0);            // a.k = 5, b.k = 1 directly
    EXPECT_EQ(final_y(s, {}, {five, two}), 2.0);            // b.k = 1 stays direct
    EXPECT_EQ(final_y(s, {"gain_k=7"}, {five, two}), 7.0);  // --set after every file
    const auto bad = s.ssv("bad.ssv", R"(<ssv:Parameter name="gain_k"><ssv:Real value="three"/></ssv:Parameter>)");
    try {
        final_y(s, {}, {bad});
        FAIL() << "a value that is no number was taken";
    } catch (const CosimError& e) {
        EXPECT_NE(std::string(e.what()).find(bad.string() + ":4: "), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("gain_k"), std::string::npos) << e.what();
    }
}

TEST(SystemParameters, InfoListsThemWithValueUnitAndWhatEachFeeds) {
    Scratch s;
    std::ostringstream out;
    print_info(s.ssd(), out);
    EXPECT_NE(out.str().find(
                  "system parameters (--set NAME=VALUE, --parameters FILE.ssv):\n  gain_k = 3  (Real) -> a.k b.k\n"),
              std::string::npos)
        << out.str();
}

}  // namespace
}  // namespace cosim
