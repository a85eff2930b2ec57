// The bundled systems, and what `cosim pack` writes from them, against the SSP 1.0 XML schemas
// (harness/systems/schema/: the Modelica Association's SSP 1.0.1 schemas, BSD 2-Clause, unchanged).
#include <gtest/gtest.h>
#include <libxml/parser.h>
#include <libxml/xmlschemas.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "fmi_loader/fmu_archive.hpp"
#include "ssp_archive.hpp"

namespace cosim {
namespace {

const std::filesystem::path schema_dir = SSP_SCHEMA_DIR;
const std::filesystem::path systems_dir = PVATT_SYSTEMS_SOURCE_DIR;

// Validates `file` against SystemStructureDescription.xsd; returns the schema's complaints (empty: valid).
std::string schema_errors(const std::filesystem::path& file) {
    std::string errors;
    xmlSchemaParserCtxtPtr parser = xmlSchemaNewParserCtxt((schema_dir / "SystemStructureDescription.xsd").c_str());
    xmlSchemaPtr schema = parser ? xmlSchemaParse(parser) : nullptr;
    if (!schema) {
        if (parser) xmlSchemaFreeParserCtxt(parser);
        return "the schema does not parse";
    }
    xmlSchemaValidCtxtPtr valid = xmlSchemaNewValidCtxt(schema);
    xmlSchemaSetValidStructuredErrors(
        valid,
        [](void* out, xmlErrorPtr e) {
            *static_cast<std::string*>(out) += std::to_string(e->line) + ": " + (e->message ? e->message : "?");
        },
        &errors);
    xmlDocPtr doc = xmlReadFile(file.c_str(), nullptr, XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING);
    if (!doc) {
        errors = "does not parse";
    } else if (xmlSchemaValidateDoc(valid, doc) != 0 && errors.empty()) {
        errors = "invalid";
    }
    if (doc) xmlFreeDoc(doc);
    xmlSchemaFreeValidCtxt(valid);
    xmlSchemaFree(schema);
    xmlSchemaFreeParserCtxt(parser);
    return errors;
}

TEST(CosimSspSchema, BundledSystemsAndTheirArchivesValidate) {
    for (const char* name : {"seed_spin", "seed_spin_hil", "leo_orbit"}) {
        const auto ssd = systems_dir / (std::string(name) + ".ssd");
        EXPECT_EQ(schema_errors(ssd), "") << ssd;
        const auto ssp =
            std::filesystem::temp_directory_path() /
            ("cosim_schema_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" + name + ".ssp");
        std::ostringstream log;
        pack_system(ssd, ssp, {PVATT_FMU_DIR}, log);
        const fmi_loader::FmuArchive unpacked(ssp);  // the zip, as any SSP importer opens it
        EXPECT_EQ(schema_errors(unpacked.directory() / "SystemStructure.ssd"), "") << ssp;
        std::filesystem::remove(ssp);
    }
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
