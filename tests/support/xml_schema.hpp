// Validates an XML file against an XML schema with libxml2: the one check both the FMI 2.0 descriptions
// (fmi2/schema) and the SSP 1.0 systems (harness/systems/schema) go through. Header-only; the test
// links LibXml2::LibXml2.
#pragma once

#include <libxml/parser.h>
#include <libxml/xmlschemas.h>

#include <filesystem>
#include <string>

namespace test_support {

// The schema's complaints about `file`, one per line with its line number; empty when the file is valid.
inline std::string xml_schema_errors(const std::filesystem::path& schema_file, const std::filesystem::path& file) {
    std::string errors;
    xmlSchemaParserCtxtPtr parser = xmlSchemaNewParserCtxt(schema_file.c_str());
    xmlSchemaPtr schema = parser ? xmlSchemaParse(parser) : nullptr;
    if (!schema) {
        if (parser) xmlSchemaFreeParserCtxt(parser);
        return "the schema " + schema_file.string() + " does not parse";
    }
    xmlSchemaValidCtxtPtr valid = xmlSchemaNewValidCtxt(schema);
    xmlSchemaSetValidStructuredErrors(
        valid,
        [](void* out, xmlErrorPtr e) {
            // libxml2's messages end in a line break of their own.
            *static_cast<std::string*>(out) += std::to_string(e->line) + ": " + (e->message ? e->message : "?\n");
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

}  // namespace test_support
