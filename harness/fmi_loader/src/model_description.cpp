// modelDescription.xml reader. The rules and defaults quoted below are from the FMI 2.0.4 standard,
// section 2.2 (the XML schema) and its table of causality/variability/initial (section 2.2.7).
#include "fmi_loader/model_description.hpp"

#include <libxml/parser.h>
#include <libxml/tree.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>

#include "description_reader.hpp"
#include "fmi/vocabulary.hpp"
#include "fmi_loader/loader_error.hpp"

namespace fmi_loader {

// The words are the runtime's (fmi/vocabulary.hpp), in the order of the enums in model_description.hpp.
static_assert(fmi_vocabulary::spelling(fmi_vocabulary::causalities, Causality::independent) == "independent");
static_assert(fmi_vocabulary::spelling(fmi_vocabulary::variabilities, Variability::continuous) == "continuous");
static_assert(fmi_vocabulary::spelling(fmi_vocabulary::initials, Initial::calculated) == "calculated");

std::string_view to_string(Causality c) noexcept {
    // FMI 3.0's structural parameter is no word of FMI 2.0's list.
    if (c == Causality::structural_parameter) return "structuralParameter";
    return fmi_vocabulary::spelling(fmi_vocabulary::causalities, c);
}

std::string_view to_string(Variability v) noexcept {
    return fmi_vocabulary::spelling(fmi_vocabulary::variabilities, v);
}

std::string_view to_string(Initial i) noexcept {
    return fmi_vocabulary::spelling(fmi_vocabulary::initials, i);
}

std::string_view to_string(VariableType t) noexcept {
    switch (t) {
        case VariableType::real:
            return "Real";
        case VariableType::integer:
            return "Integer";
        case VariableType::boolean:
            return "Boolean";
        case VariableType::string:
            return "String";
        case VariableType::enumeration:
            return "Enumeration";
    }
    return "?";
}

std::string_view to_string(Fmi3Type t) noexcept {
    switch (t) {
        case Fmi3Type::float32:
            return "Float32";
        case Fmi3Type::float64:
            return "Float64";
        case Fmi3Type::int8:
            return "Int8";
        case Fmi3Type::uint8:
            return "UInt8";
        case Fmi3Type::int16:
            return "Int16";
        case Fmi3Type::uint16:
            return "UInt16";
        case Fmi3Type::int32:
            return "Int32";
        case Fmi3Type::uint32:
            return "UInt32";
        case Fmi3Type::int64:
            return "Int64";
        case Fmi3Type::uint64:
            return "UInt64";
        case Fmi3Type::boolean:
            return "Boolean";
        case Fmi3Type::string:
            return "String";
        case Fmi3Type::binary:
            return "Binary";
        case Fmi3Type::enumeration:
            return "Enumeration";
        case Fmi3Type::clock:
            return "Clock";
    }
    return "?";
}

VariableType base_kind(Fmi3Type t) noexcept {
    switch (t) {
        case Fmi3Type::float32:
        case Fmi3Type::float64:
            return VariableType::real;
        case Fmi3Type::boolean:
        case Fmi3Type::clock:
            return VariableType::boolean;
        case Fmi3Type::string:
        case Fmi3Type::binary:
            return VariableType::string;
        case Fmi3Type::enumeration:
            return VariableType::enumeration;
        default:
            return VariableType::integer;
    }
}

// The FMI 3.0 tables (section 2.4.7.4) equal FMI 2.0's for the causalities both have; a structural
// parameter behaves as a parameter (fixed or tunable, initial exact).
bool is_valid_combination(Causality c, Variability v) noexcept {
    using enum Variability;
    switch (c) {
        case Causality::structural_parameter:
        case Causality::parameter:
        case Causality::calculated_parameter:
            return v == fixed || v == tunable;
        case Causality::input:
            return v == discrete || v == continuous;
        case Causality::output:
            return v == constant || v == discrete || v == continuous;
        case Causality::local:
            return true;
        case Causality::independent:
            return v == continuous;
    }
    return false;
}

Initial default_initial(Causality c, Variability v) noexcept {
    // Cases of the 2.2.7 table: A -> exact, B and C -> calculated, D and E -> no initial.
    switch (c) {
        case Causality::parameter:
        case Causality::structural_parameter:
            return Initial::exact;  // A
        case Causality::calculated_parameter:
            return Initial::calculated;  // B
        case Causality::input:
        case Causality::independent:
            return Initial::none;  // D, E
        case Causality::output:
        case Causality::local:
            return v == Variability::constant ? Initial::exact : Initial::calculated;  // A; B or C
    }
    return Initial::none;
}

bool is_allowed_initial(Causality c, Variability v, Initial i) noexcept {
    if (!is_valid_combination(c, v)) return false;
    switch (c) {
        case Causality::parameter:
        case Causality::structural_parameter:
            return i == Initial::exact;  // A
        case Causality::calculated_parameter:
            return i == Initial::calculated || i == Initial::approx;  // B
        case Causality::input:
        case Causality::independent:
            return i == Initial::none;  // D, E
        case Causality::output:
        case Causality::local:
            if (v == Variability::constant) return i == Initial::exact;  // A
            if (v == Variability::fixed || v == Variability::tunable)
                return i == Initial::calculated || i == Initial::approx;                     // B
            return i == Initial::exact || i == Initial::approx || i == Initial::calculated;  // C
    }
    return false;
}

std::optional<double> ScalarVariable::start_as_real() const {
    if (!start || type == VariableType::string || type == VariableType::boolean) return std::nullopt;
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(start->c_str(), &end);
    if (end == start->c_str() || *end != '\0' || errno == ERANGE) return std::nullopt;
    return value;
}

std::optional<bool> ScalarVariable::start_as_boolean() const {
    if (!start || type != VariableType::boolean) return std::nullopt;
    if (*start == "true" || *start == "1") return true;
    if (*start == "false" || *start == "0") return false;
    return std::nullopt;
}

const ScalarVariable* ModelDescription::find_variable(std::string_view name) const noexcept {
    for (const auto& v : model_variables)
        if (v.name == name) return &v;
    return nullptr;
}

const ScalarVariable* ModelDescription::find_by_reference(std::uint32_t value_reference) const noexcept {
    for (const auto& v : model_variables)
        if (v.value_reference == value_reference) return &v;
    return nullptr;
}

namespace {

// A dimension's size: its own start, or the start value of the structural parameter it names (0 when
// that is missing or not a whole UInt64: the reader refuses such a description, see check3).
std::size_t dimension_size(const ModelDescription& md, const Dimension& d) noexcept {
    if (d.start) return static_cast<std::size_t>(*d.start);
    const ScalarVariable* p = d.value_reference ? md.find_by_reference(*d.value_reference) : nullptr;
    return static_cast<std::size_t>(p ? dimension_start(*p).value_or(0) : 0);
}

}  // namespace

std::optional<std::uint64_t> dimension_start(const ScalarVariable& p) noexcept {
    if (!p.start) return std::nullopt;
    std::string_view text = *p.start;
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t' || text.front() == '\n'))
        text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\n')) text.remove_suffix(1);
    std::uint64_t x = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return x;
}

std::vector<std::size_t> ModelDescription::extents(const ScalarVariable& v) const {
    std::vector<std::size_t> out;
    for (const auto& d : v.dimensions) out.push_back(dimension_size(*this, d));
    return out;
}

std::size_t ModelDescription::element_count(const ScalarVariable& v) const noexcept {
    std::size_t n = 1;
    for (const auto& d : v.dimensions) n *= dimension_size(*this, d);
    return n;
}

std::size_t ModelDescription::number_of_continuous_states() const noexcept {
    if (!is_fmi3()) return model_structure.derivatives.size();
    std::size_t n = 0;
    for (const auto& u : model_structure.derivatives) n += element_count(model_variables[u.index - 1]);
    return n;
}

const Unit* ModelDescription::find_unit(std::string_view name) const noexcept {
    for (const auto& u : unit_definitions)
        if (u.name == name) return &u;
    return nullptr;
}

const SimpleType* ModelDescription::find_type(std::string_view name) const noexcept {
    for (const auto& t : type_definitions)
        if (t.name == name) return &t;
    return nullptr;
}

namespace {

struct DocFree {
    void operator()(xmlDoc* d) const noexcept { xmlFreeDoc(d); }
};
struct CtxtFree {
    void operator()(xmlParserCtxt* c) const noexcept { xmlFreeParserCtxt(c); }
};

struct FirstError {
    std::string message;
    int line = 0;
    // libxml2 passes the parser context as user data; _private points back at this record.
    static void record(void* user, xmlErrorPtr error) {
        auto* ctxt = static_cast<xmlParserCtxt*>(user);
        auto* self = ctxt ? static_cast<FirstError*>(ctxt->_private) : nullptr;
        if (!self || !error || !self->message.empty() || error->level < XML_ERR_ERROR) return;
        self->message = error->message ? error->message : "error";
        self->line = error->line;
    }
};

}  // namespace

ModelDescription parse_model_description(std::string_view xml, const std::string& source_name, const Limits& limits) {
    if (xml.size() > limits.max_description_bytes)
        throw LoaderError(LoaderErrc::limit,
                          "'" + source_name + "' is " + std::to_string(xml.size()) + " bytes, more than the limit of " +
                              std::to_string(limits.max_description_bytes) + " bytes (max_description_bytes)");
    std::unique_ptr<xmlParserCtxt, CtxtFree> ctxt(xmlNewParserCtxt());
    if (!ctxt) throw LoaderError(LoaderErrc::xml_parse, "'" + source_name + "': cannot create parser");
    // NONET: no network; neither DTDLOAD nor NOENT: no external subset and no entity expansion.
    // NOERROR/NOWARNING: the message goes into the exception, not to stderr.
    const int options = XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING;
    // The first error says what is wrong ("AttValue length too long"); the last is often a consequence
    // ("Extra content at the end of the document").
    FirstError first;
    ctxt->sax->serror = &FirstError::record;
    ctxt->_private = &first;
    std::unique_ptr<xmlDoc, DocFree> doc(
        xmlCtxtReadMemory(ctxt.get(), xml.data(), static_cast<int>(xml.size()), nullptr, nullptr, options));
    if (!doc || !ctxt->wellFormed) {
        const xmlError* last = xmlCtxtGetLastError(ctxt.get());
        std::string cause = !first.message.empty()  ? first.message
                            : last && last->message ? last->message
                                                    : "not well-formed";
        while (!cause.empty() && cause.back() == '\n') cause.pop_back();
        const int line = !first.message.empty() ? first.line : last ? last->line : 0;
        throw LoaderError(LoaderErrc::xml_parse, "'" + source_name + "' line " + std::to_string(line) + ": " + cause);
    }
    // A DOCTYPE is the only way to declare entities; FMI never uses one, so refuse it outright.
    if (doc->intSubset || doc->extSubset)
        throw LoaderError(LoaderErrc::xml_invalid,
                          "'" + source_name + "': DOCTYPE declarations are not allowed in modelDescription.xml");
    return detail::Reader(source_name, limits).read(xmlDocGetRootElement(doc.get()));
}

ModelDescription read_model_description(const std::filesystem::path& file, const Limits& limits) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw LoaderError(LoaderErrc::xml_parse, "'" + file.string() + "': cannot open file");
    // The size is checked before a byte is read: a 2 GB file must not be read into memory first.
    std::error_code ec;
    const auto size = std::filesystem::file_size(file, ec);
    if (!ec && size > limits.max_description_bytes)
        throw LoaderError(LoaderErrc::limit,
                          "'" + file.string() + "' is " + std::to_string(size) + " bytes, more than the limit of " +
                              std::to_string(limits.max_description_bytes) + " bytes (max_description_bytes)");
    std::string content;
    content.resize(ec ? 0 : static_cast<std::size_t>(size));
    in.read(content.data(), static_cast<std::streamsize>(content.size()));
    if (in.gcount() != static_cast<std::streamsize>(content.size()) || ec)
        throw LoaderError(LoaderErrc::xml_parse,
                          "'" + file.string() + "': cannot read the file" + (ec ? ": " + ec.message() : ""));
    return parse_model_description(content, file.string(), limits);
}

}  // namespace fmi_loader
