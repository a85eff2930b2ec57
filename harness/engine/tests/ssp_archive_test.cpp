// SSP archives: what `cosim pack` writes runs exactly as the .ssd it came from; broken archives are
// refused with a reason.
#include <gtest/gtest.h>
#include <zip.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/cosim_error.hpp"
#include "engine/execution.hpp"
#include "engine/ssp_archive.hpp"
#include "engine/system.hpp"

namespace cosim {
namespace {

const std::filesystem::path fmu_dir = COSIM_TEST_FMU_DIR;

std::filesystem::path temp(const std::string& name) {
    return std::filesystem::temp_directory_path() /
           ("cosim_ssp_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" + name);
}

// gain.y = k u with k = -0.5 fed back into the integrator: x(t) = exp(-0.5 t).
void write_ssd(const std::filesystem::path& path) {
    std::ofstream(path) << R"(<?xml version="1.0" encoding="UTF-8"?>
<ssd:SystemStructureDescription xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription"
    xmlns:ssc="http://ssp-standard.org/SSP1/SystemStructureCommon"
    xmlns:ssv="http://ssp-standard.org/SSP1/SystemStructureParameterValues" version="1.0" name="loop">
  <ssd:System name="loop">
    <ssd:Elements>
      <ssd:Component name="int" source="test_integrator.fmu"/>
      <ssd:Component name="gain" source="test_gain.fmu">
        <ssd:ParameterBindings><ssd:ParameterBinding><ssd:ParameterValues><ssv:ParameterSet version="1.0" name="p">
          <ssv:Parameters><ssv:Parameter name="k"><ssv:Real value="-0.5"/></ssv:Parameter></ssv:Parameters>
        </ssv:ParameterSet></ssd:ParameterValues></ssd:ParameterBinding></ssd:ParameterBindings>
      </ssd:Component>
    </ssd:Elements>
    <ssd:Connections>
      <ssd:Connection startElement="int" startConnector="y" endElement="gain" endConnector="u"/>
      <ssd:Connection startElement="gain" startConnector="y" endElement="int" endConnector="u"/>
    </ssd:Connections>
  </ssd:System>
  <ssd:DefaultExperiment startTime="0" stopTime="1"/>
</ssd:SystemStructureDescription>
)";
}

std::vector<double> run_y(const std::filesystem::path& system_file, std::vector<std::filesystem::path> fmu_dirs = {}) {
    SystemOptions o;
    o.fmu_dirs = std::move(fmu_dirs);  // none for an archive: it must carry its FMUs
    System system(read_system_description(system_file), o);
    struct Probe : Observer {
        std::vector<double> y;
        void sample(double, System& s) override {
            const auto i = s.component_index("int");
            y.push_back(s.components()[i].instance->get_real(
                s.components()[i].description().find_variable("y")->value_reference));
        }
    } probe;
    ExecutionOptions ex;
    ex.stop_time = 1.0;
    ex.output_interval = 0.25;
    ex.relative_tolerance = 1e-9;
    Execution(system, ex).run({&probe});
    return probe.y;
}

TEST(CosimSsp, PackedArchiveRunsExactlyAsItsSsd) {
    const auto ssd = temp("loop.ssd"), ssp = temp("loop.ssp");
    write_ssd(ssd);
    std::ostringstream log;
    pack_system(ssd, ssp, {.fmu_dirs = {fmu_dir}, .oms_step = {}}, log);
    ASSERT_TRUE(std::filesystem::exists(ssp));
    EXPECT_FALSE(std::filesystem::exists(ssp.string() + ".partial"));
    const auto packed = run_y(ssp);
    ASSERT_EQ(packed.size(), 5u);
    EXPECT_EQ(packed, run_y(ssd, {fmu_dir}));  // bit for bit
    for (std::size_t k = 0; k < packed.size(); ++k) EXPECT_NEAR(packed[k], std::exp(-0.5 * 0.25 * k), 1e-6);
    EXPECT_THROW(pack_system(ssd, temp("missing.ssp"), {}, log), CosimError);  // FMUs nowhere: nothing written
    EXPECT_FALSE(std::filesystem::exists(temp("missing.ssp")));
    std::filesystem::remove(ssd);
    std::filesystem::remove(ssp);
}

// The loop with k a system parameter (gain_k = -0.5) and the integrator's tau bound at the system level by
// its hierarchical name (int.tau = 2): x(t) = exp(-0.25 t). Packed, the values are the components' own
// bindings (OMSimulator 2.1.3 connects no system parameter named like "inertia[1]"), and the archive runs
// bit for bit as the .ssd.
TEST(CosimSsp, PackResolvesSystemParametersIntoTheComponentsBindings) {
    const auto ssd = temp("scenario.ssd"), ssp = temp("scenario.ssp");
    std::ofstream(ssd) << R"(<?xml version="1.0" encoding="UTF-8"?>
<ssd:SystemStructureDescription xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription"
    xmlns:ssc="http://ssp-standard.org/SSP1/SystemStructureCommon"
    xmlns:ssv="http://ssp-standard.org/SSP1/SystemStructureParameterValues" version="1.0" name="loop">
  <ssd:System name="loop">
    <ssd:Connectors><ssd:Connector name="gain_k" kind="parameter"><ssc:Real unit="1"/></ssd:Connector></ssd:Connectors>
    <ssd:ParameterBindings><ssd:ParameterBinding><ssd:ParameterValues><ssv:ParameterSet version="1.0" name="s">
      <ssv:Parameters>
        <ssv:Parameter name="gain_k"><ssv:Real unit="1" value="-0.5"/></ssv:Parameter>
        <ssv:Parameter name="int.tau"><ssv:Real unit="s" value="2"/></ssv:Parameter>
      </ssv:Parameters>
    </ssv:ParameterSet></ssd:ParameterValues></ssd:ParameterBinding></ssd:ParameterBindings>
    <ssd:Elements>
      <ssd:Component name="int" source="test_integrator.fmu"/>
      <ssd:Component name="gain" source="test_gain.fmu">
        <ssd:Connectors><ssd:Connector name="k" kind="parameter"><ssc:Real unit="1"/></ssd:Connector>
          <ssd:Connector name="u" kind="input"><ssc:Real unit="V"/></ssd:Connector>
          <ssd:Connector name="y" kind="output"><ssc:Real unit="V"/></ssd:Connector></ssd:Connectors>
      </ssd:Component>
    </ssd:Elements>
    <ssd:Connections>
      <ssd:Connection startElement="int" startConnector="y" endElement="gain" endConnector="u"/>
      <ssd:Connection startElement="gain" startConnector="y" endElement="int" endConnector="u"/>
      <ssd:Connection startConnector="gain_k" endElement="gain" endConnector="k"/>
    </ssd:Connections>
  </ssd:System>
  <ssd:DefaultExperiment startTime="0" stopTime="1"/>
</ssd:SystemStructureDescription>
)";
    std::ostringstream log;
    pack_system(ssd, ssp, {.fmu_dirs = {fmu_dir}, .oms_step = {}}, log);
    const SystemDescription packed = read_system_description(ssp);
    EXPECT_TRUE(packed.parameters.empty());
    EXPECT_TRUE(packed.feeds.empty());
    EXPECT_TRUE(packed.system_bindings.values.empty());
    ASSERT_EQ(packed.components.at(1).parameters.size(), 1u);
    EXPECT_EQ(packed.components[1].parameters[0].variable, "k");
    EXPECT_EQ(packed.components[1].parameters[0].value, "-0.5");
    ASSERT_EQ(packed.components.at(0).parameters.size(), 1u);
    EXPECT_EQ(packed.components[0].parameters[0].variable, "tau");
    const auto y = run_y(ssp);
    EXPECT_EQ(y, run_y(ssd, {fmu_dir}));  // bit for bit
    ASSERT_EQ(y.size(), 5u);
    for (std::size_t k = 0; k < y.size(); ++k) EXPECT_NEAR(y[k], std::exp(-0.25 * 0.25 * k), 1e-6);
    std::filesystem::remove(ssd);
    std::filesystem::remove(ssp);
}

void write_zip(const std::filesystem::path& path, const std::vector<std::pair<std::string, std::string>>& entries) {
    int error = 0;
    zip_t* z = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
    ASSERT_NE(z, nullptr);
    for (const auto& [name, text] : entries) {
        zip_source_t* s = zip_source_buffer(z, text.data(), text.size(), 0);
        ASSERT_GE(zip_file_add(z, name.c_str(), s, ZIP_FL_ENC_UTF_8), 0);
    }
    ASSERT_EQ(zip_close(z), 0);
}

TEST(CosimSsp, BrokenArchivesAreRefused) {
    const auto no_ssd = temp("no_ssd.ssp"), escape = temp("escape.ssp"), not_zip = temp("not_zip.ssp");
    write_zip(no_ssd, {{"resources/readme.txt", "no system here"}});
    write_zip(escape, {{"../evil.ssd", "<x/>"}});
    std::ofstream(not_zip) << "plain text";
    EXPECT_THROW(read_system_description(no_ssd), CosimError);
    EXPECT_THROW(read_system_description(escape), CosimError);
    EXPECT_THROW(read_system_description(not_zip), CosimError);
    for (const auto& p : {no_ssd, escape, not_zip}) std::filesystem::remove(p);
}

// --- issue 24: an .ssp is a closed world ---

std::string slurp_file(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// A system of one gain whose source and optional parameter binding are as given.
std::string one_gain_ssd(const std::string& source, const std::string& binding = "") {
    return R"(<?xml version="1.0" encoding="UTF-8"?>
<ssd:SystemStructureDescription xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription"
    xmlns:ssc="http://ssp-standard.org/SSP1/SystemStructureCommon" version="1.0" name="g">
  <ssd:System name="g"><ssd:Elements><ssd:Component name="gain" source=")" +
           source + R"(">)" + binding + R"(</ssd:Component></ssd:Elements></ssd:System>
  <ssd:DefaultExperiment startTime="0" stopTime="1"/>
</ssd:SystemStructureDescription>
)";
}

const std::string gain_params = R"(<?xml version="1.0" encoding="UTF-8"?>
<ssv:ParameterSet xmlns:ssv="http://ssp-standard.org/SSP1/SystemStructureParameterValues" version="1.0" name="p">
  <ssv:Parameters><ssv:Parameter name="k"><ssv:Real value="-0.5"/></ssv:Parameter></ssv:Parameters>
</ssv:ParameterSet>
)";

TEST(CosimSsp, AnArchiveReadsNothingOutsideItself) {
    const auto outside_ssv = temp("outside.ssv");
    std::ofstream(outside_ssv) << gain_params;
    const std::string fmu = (fmu_dir / "test_gain.fmu").string();
    const std::string in_archive = "resources/test_gain.fmu";
    const std::string binding_to = R"(<ssd:ParameterBindings><ssd:ParameterBinding source=")";
    const std::string binding_end = R"("/></ssd:ParameterBindings>)";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"absolute source", one_gain_ssd(fmu)},
        {"file: URI", one_gain_ssd("file://" + fmu)},
        {"climbing source", one_gain_ssd("resources/../../" + fmu_dir.filename().string() + "/test_gain.fmu")},
        {"http: URI", one_gain_ssd("http://example.org/test_gain.fmu")},
        {"not in the archive (the build folder has it)", one_gain_ssd("test_gain.fmu")},
        {"absolute parameter file", one_gain_ssd(in_archive, binding_to + outside_ssv.string() + binding_end)},
        {"parameter file from stdin", one_gain_ssd(in_archive, binding_to + "/dev/stdin" + binding_end)},
        {"climbing parameter file",
         one_gain_ssd(in_archive, binding_to + "../" + outside_ssv.filename().string() + binding_end)},
    };
    const std::string gain_fmu = slurp_file(fmu);
    for (const auto& [what, ssd] : cases) {
        const auto ssp = temp("closed.ssp");
        write_zip(ssp, {{"SystemStructure.ssd", ssd}, {in_archive, gain_fmu}});
        try {
            SystemOptions o;
            o.fmu_dirs = {fmu_dir};  // where the build keeps test_gain.fmu: an archive must not look there
            System system(read_system_description(ssp), o);
            ADD_FAILURE() << what << ": accepted";
        } catch (const CosimError& e) {
            EXPECT_NE(std::string(e.what()).find("refused"), std::string::npos) << what << ": " << e.what();
        }
        std::filesystem::remove(ssp);
    }
    std::filesystem::remove(outside_ssv);
}

// Components of one FMU share one unpacked copy (a 2.4 MB archive used to write 2.6 GB).
TEST(CosimSsp, EachFmuIsUnpackedOncePerSystem) {
    const auto folder = temp("unpack_once"), ssd = temp("five.ssd");
    std::filesystem::create_directories(folder);
    const char* old_tmp = std::getenv("TMPDIR");
    const std::string saved = old_tmp ? old_tmp : "";
    ::setenv("TMPDIR", folder.c_str(), 1);
    std::string elements;
    for (int i = 0; i < 5; ++i)
        elements += R"(<ssd:Component name="g)" + std::to_string(i) + R"(" source="test_gain.fmu"/>)";
    std::ofstream(ssd) << R"(<?xml version="1.0" encoding="UTF-8"?>
<ssd:SystemStructureDescription xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription" version="1.0" name="f">
  <ssd:System name="f"><ssd:Elements>)"
                       << elements << R"(</ssd:Elements></ssd:System></ssd:SystemStructureDescription>
)";
    {
        SystemOptions o;
        o.fmu_dirs = {fmu_dir};
        System system(read_system_description(ssd), o);
        EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder), std::filesystem::directory_iterator()), 1);
    }
    if (old_tmp)
        ::setenv("TMPDIR", saved.c_str(), 1);
    else
        ::unsetenv("TMPDIR");
    std::filesystem::remove(ssd);
    std::filesystem::remove_all(folder);
}

// pack takes the parameter files a system binds: the archive runs without them beside it.
TEST(CosimSsp, PackCarriesParameterFiles) {
    const auto folder = temp("with_ssv");
    std::filesystem::create_directories(folder);
    const auto ssd = folder / "loop.ssd", ssp = temp("with_ssv.ssp");
    write_ssd(ssd);
    std::string text = slurp_file(ssd);
    const std::string inline_binding =
        text.substr(text.find("<ssd:ParameterBindings>"),
                    text.find("</ssd:ParameterBindings>") + 24 - text.find("<ssd:ParameterBindings>"));
    text.replace(text.find(inline_binding), inline_binding.size(),
                 R"(<ssd:ParameterBindings><ssd:ParameterBinding source="gain.ssv"/></ssd:ParameterBindings>)");
    std::ofstream(ssd) << text;
    std::ofstream(folder / "gain.ssv") << gain_params;
    std::ostringstream log;
    pack_system(ssd, ssp, {.fmu_dirs = {fmu_dir}, .oms_step = {}}, log);
    std::filesystem::remove_all(folder);  // nothing beside the archive any more
    const auto y = run_y(ssp);
    ASSERT_EQ(y.size(), 5u);
    for (std::size_t k = 0; k < y.size(); ++k) EXPECT_NEAR(y[k], std::exp(-0.5 * 0.25 * k), 1e-6);
    std::filesystem::remove(ssp);
}

}  // namespace
}  // namespace cosim
