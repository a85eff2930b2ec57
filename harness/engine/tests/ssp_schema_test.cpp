// The bundled systems, and what `cosim pack` writes from them, against the SSP 1.0 XML schemas
// (harness/systems/schema/: the Modelica Association's SSP 1.0.1 schemas, BSD 2-Clause, unchanged).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "engine/ssp_archive.hpp"
#include "engine/system_description.hpp"
#include "fmi_loader/fmu_archive.hpp"
#include "xml_schema.hpp"

namespace cosim {
namespace {

const std::filesystem::path schema_dir = SSP_SCHEMA_DIR;
const std::filesystem::path systems_dir = PVATT_SYSTEMS_SOURCE_DIR;

// Validates `file` against SystemStructureDescription.xsd; returns the schema's complaints (empty: valid).
std::string schema_errors(const std::filesystem::path& file) {
    return test_support::xml_schema_errors(schema_dir / "SystemStructureDescription.xsd", file);
}

TEST(CosimSspSchema, BundledSystemsAndTheirArchivesValidate) {
    for (const char* name : {"seed_spin", "seed_spin_hil", "seed_spin_pil", "leo_orbit"}) {
        const auto ssd = systems_dir / (std::string(name) + ".ssd");
        EXPECT_EQ(schema_errors(ssd), "") << ssd;
        const auto ssp =
            std::filesystem::temp_directory_path() /
            ("cosim_schema_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" + name + ".ssp");
        std::ostringstream log;
        pack_system(ssd, ssp, {.fmu_dirs = {PVATT_FMU_DIR}, .oms_step = {}}, log);
        const fmi_loader::FmuArchive unpacked(ssp);  // the zip, as any SSP importer opens it
        EXPECT_EQ(schema_errors(unpacked.directory() / "SystemStructure.ssd"), "") << ssp;
        std::filesystem::remove(ssp);
    }
}

// The bundled parameter sets (harness/systems/parameters) against SystemStructureParameterValues.xsd.
TEST(CosimSspSchema, BundledParameterSetsValidate) {
    int files = 0;
    for (const auto& e : std::filesystem::directory_iterator(systems_dir / "parameters")) {
        if (e.path().extension() != ".ssv") continue;
        ++files;
        EXPECT_EQ(test_support::xml_schema_errors(schema_dir / "SystemStructureParameterValues.xsd", e.path()), "")
            << e.path();
        EXPECT_FALSE(read_parameter_values(e.path()).values.empty()) << e.path();
    }
    EXPECT_GE(files, 1);
}

std::string read_text(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// What makes the archive travel (ssp_archive.hpp): choices bound by value, the components' hints at the
// system level (read back the same), OMSimulator's annotation first with the system's step.
TEST(CosimSspSchema, PackedSystemIsPortableAndReadsBackTheSame) {
    const auto ssd = systems_dir / "seed_spin_hil.ssd";
    const auto ssp = std::filesystem::temp_directory_path() /
                     ("cosim_portable_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + ".ssp");
    std::ostringstream log;
    pack_system(ssd, ssp, {.fmu_dirs = {PVATT_FMU_DIR}, .oms_step = {}}, log);
    const SystemDescription original = read_system_description(ssd), packed = read_system_description(ssp);
    const fmi_loader::FmuArchive unpacked(ssp);
    const std::string xml = read_text(unpacked.directory() / "SystemStructure.ssd");
    EXPECT_EQ(xml.find("ssv:String"), std::string::npos) << "every choice of the bundled systems is an Enumeration";
    EXPECT_NE(xml.find(R"(<ssv:Parameter name="fidelity"><ssv:Integer value="0"/>)"), std::string::npos);
    const auto system_annotations = xml.find("<ssd:Annotations>", xml.find("</ssd:Connections>"));
    ASSERT_NE(system_annotations, std::string::npos);
    EXPECT_LT(xml.find(R"(type="org.openmodelica")", system_annotations),
              xml.find(R"(type="org.pvatt.execution")", system_annotations));
    EXPECT_NE(xml.find(R"(<oms:FixedStepMaster description="oms-ma" stepSize="0.001")"), std::string::npos);
    ASSERT_EQ(packed.components.size(), original.components.size());
    for (std::size_t i = 0; i < original.components.size(); ++i) {
        const auto &a = original.components[i], &b = packed.components[i];
        EXPECT_EQ(a.execution.has_value(), b.execution.has_value()) << a.name;
        if (a.execution && b.execution) {
            EXPECT_EQ(a.execution->co_simulation, b.execution->co_simulation);
            EXPECT_EQ(a.execution->communication_step, b.execution->communication_step);
        }
        EXPECT_EQ(a.bridge.has_value(), b.bridge.has_value()) << a.name;
        if (a.bridge && b.bridge) {
            EXPECT_EQ(a.bridge->port, b.bridge->port);
        }
    }
    std::filesystem::remove(ssp);
}

TEST(CosimSspSchema, TheCheckFindsAnInvalidFile) {
    const auto bad = std::filesystem::temp_directory_path() / "cosim_schema_bad.ssd";
    std::ofstream(bad) << R"(<?xml version="1.0"?>
<ssd:SystemStructureDescription xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription" version="1.0"
    name="bad"><ssd:Nonsense/></ssd:SystemStructureDescription>
)";
    EXPECT_NE(schema_errors(bad), "");
    std::filesystem::remove(bad);
}

}  // namespace
}  // namespace cosim
