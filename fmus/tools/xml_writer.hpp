// The libxml2 text writer both model-description writers use (FMI 2.0 and 3.0), so every attribute is
// escaped the same way, and the <Unit> element, which both versions spell alike. Build-time only.
#pragma once

#include <libxml/xmlwriter.h>

#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "fmu/description.hpp"
#include "fmu/errors.hpp"
#include "fmu/model.hpp"
#include "fmu/units.hpp"
#include "fmu/variable.hpp"

namespace fmu {

struct BufferDeleter {
    void operator()(xmlBuffer* b) const { xmlBufferFree(b); }
};
struct WriterDeleter {
    void operator()(xmlTextWriter* w) const { xmlFreeTextWriter(w); }
};

class Writer {
public:
    Writer() : buffer_(xmlBufferCreate()) {
        if (!buffer_) throw Error("libxml2: cannot create a buffer");
        writer_.reset(xmlNewTextWriterMemory(buffer_.get(), 0));
        if (!writer_) throw Error("libxml2: cannot create a writer");
        xmlTextWriterSetIndent(writer_.get(), 1);
        xmlTextWriterSetIndentString(writer_.get(), BAD_CAST "  ");
        ok(xmlTextWriterStartDocument(writer_.get(), nullptr, "UTF-8", nullptr));
    }
    void start(const char* element) { ok(xmlTextWriterStartElement(writer_.get(), BAD_CAST element)); }
    void end() { ok(xmlTextWriterEndElement(writer_.get())); }
    void attribute(const char* name, const std::string& value) {
        ok(xmlTextWriterWriteAttribute(writer_.get(), BAD_CAST name, BAD_CAST value.c_str()));
    }
    void attribute(const char* name, int value) { attribute(name, std::to_string(value)); }
    std::string finish() {
        ok(xmlTextWriterEndDocument(writer_.get()));
        writer_.reset();  // flushes into the buffer
        return std::string(reinterpret_cast<const char*>(xmlBufferContent(buffer_.get())));
    }

private:
    static void ok(int rc) {
        if (rc < 0) throw Error("libxml2 writer failed");
    }
    std::unique_ptr<xmlBuffer, BufferDeleter> buffer_;
    std::unique_ptr<xmlTextWriter, WriterDeleter> writer_;
};

inline void write_unit(Writer& w, const UnitDefinition& u) {
    w.start("Unit");
    w.attribute("name", std::string(u.name));
    w.start("BaseUnit");
    const std::pair<const char*, int> exponents[] = {{"kg", u.kg}, {"m", u.m},     {"s", u.s},   {"A", u.A},
                                                     {"K", u.K},   {"mol", u.mol}, {"cd", u.cd}, {"rad", u.rad}};
    for (auto [name, e] : exponents)
        if (e != 0) w.attribute(name, e);
    if (u.factor != 1.0) w.attribute("factor", format_real(u.factor));
    if (u.offset != 0.0) w.attribute("offset", format_real(u.offset));
    w.end();
    w.end();
}

// <UnitDefinitions> with every unit the variables use, and `extra` (FMI 3.0's time in "s").
inline void write_unit_definitions(Writer& w, const std::vector<Variable>& vars, std::set<std::string> extra = {}) {
    std::set<std::string> names = std::move(extra);
    for (const auto& v : vars)
        if (!v.unit.empty()) names.insert(v.unit);
    if (names.empty()) return;
    w.start("UnitDefinitions");
    for (const auto& name : names) {
        const auto unit = find_unit(name);
        if (!unit) throw Error("unit '" + name + "' has no definition");
        write_unit(w, *unit);
    }
    w.end();
}

// FMI 2.0 section 2.2.8 and FMI 3.0 section 2.4.8 alike: the initial unknowns are the outputs, states
// and derivatives with initial approx or calculated, and the calculated parameters.
inline bool is_initial_unknown(const Variable& v) {
    const bool calculated = v.initial == Initial::approx || v.initial == Initial::calculated;
    return (v.causality == Causality::output && calculated) || v.causality == Causality::calculated_parameter ||
           ((v.is_state() || v.is_derivative()) && calculated);
}

// An enumeration's <Item> elements, spelt alike in FMI 2.0's <Enumeration> and FMI 3.0's <EnumerationType>.
inline void write_items(Writer& w, const std::vector<EnumerationItem>& items) {
    for (const auto& item : items) {
        w.start("Item");
        w.attribute("name", item.name);
        w.attribute("value", item.value);
        w.end();
    }
}

// <LogCategories> from the runtime's names and descriptions (both versions spell it alike).
template <std::size_t N>
void write_log_categories(Writer& w, const char* const (&names)[N], const char* const (&descriptions)[N]) {
    w.start("LogCategories");
    for (std::size_t i = 0; i < N; ++i) {
        w.start("Category");
        w.attribute("name", names[i]);
        w.attribute("description", descriptions[i]);
        w.end();
    }
    w.end();
}

// <DefaultExperiment> (both versions spell it alike).
inline void write_default_experiment(Writer& w, const DefaultExperiment& ex) {
    w.start("DefaultExperiment");
    w.attribute("startTime", format_real(ex.start_time));
    w.attribute("stopTime", format_real(ex.stop_time));
    w.attribute("tolerance", format_real(ex.tolerance));
    w.attribute("stepSize", format_real(ex.step_size));
    w.end();
}

}  // namespace fmu
