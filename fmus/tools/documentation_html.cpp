#include "documentation_html.hpp"

#include <utility>

#include "fmu/description.hpp"
#include "fmu/value_access.hpp"

namespace fmu {

namespace {

std::string escape(std::string_view text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

// An Enumeration's items with their numbers: an importer that sets it by value (FMPy's start_values,
// fmi2SetInteger) needs the number, a reader the name.
std::string items_with_numbers(const Variable& v) {
    std::string out;
    for (const auto& item : v.items) {
        if (!out.empty()) out += ", ";
        out += item.name + " = " + std::to_string(item.value);
    }
    return out;
}

std::string range_text(const Variable& v) {
    if (v.type == ValueType::Enumeration) return items_with_numbers(v);
    if (!v.min && !v.max) return "";
    return "[" + (v.min ? format_real(*v.min) : std::string("−∞")) + ", " +
           (v.max ? format_real(*v.max) : std::string("∞")) + "]";
}

// A choice's start by item name and number (the model description gives only the number).
std::string shown_start(const Variable& v, std::span<const std::byte> bytes) {
    if (v.type == ValueType::Enumeration)
        if (const auto* item = v.item_valued(read_integer(bytes, v)))
            return item->name + " (" + std::to_string(item->value) + ")";
    return start_text(v, bytes);
}

}  // namespace

std::string documentation_html(const Model& model) {
    const auto& info = model.info();
    auto defaults = model.clone();
    defaults->reset_to_defaults();
    const auto bytes = std::as_const(*defaults).bytes();

    std::string html =
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + escape(info.model_name) +
        "</title>\n<style>body{font-family:sans-serif;max-width:60em;margin:auto}"
        "table{border-collapse:collapse}td,th{border:1px solid #999;padding:2px 6px;text-align:left}"
        "</style>\n</head>\n<body>\n<h1>" +
        escape(info.model_name) + "</h1>\n<p>" + escape(info.description) + "</p>\n" + info.documentation_html + "\n";
    html += "<p>FMI 2.0, Model Exchange and Co-Simulation, binaries for linux64. Model identifier <code>" +
            escape(info.model_identifier) + "</code>, GUID <code>" + description_guid(model) +
            "</code>. Default experiment: " + format_real(info.default_experiment.start_time) + " s to " +
            format_real(info.default_experiment.stop_time) + " s, step " +
            format_real(info.default_experiment.step_size) + " s, tolerance " +
            format_real(info.default_experiment.tolerance) + ".</p>\n";

    const std::pair<const char*, Causality> sections[] = {{"Parameters", Causality::parameter},
                                                          {"Calculated parameters", Causality::calculated_parameter},
                                                          {"Inputs", Causality::input},
                                                          {"Outputs", Causality::output},
                                                          {"States and other local variables", Causality::local}};
    for (auto [title, causality] : sections) {
        std::string rows;
        for (const auto& v : model.table().variables()) {
            if (v.causality != causality) continue;
            rows += "<tr><td><code>" + escape(v.name) + "</code></td><td>" + std::string(to_string(v.type)) +
                    "</td><td>" + escape(v.unit) + "</td><td>" + (v.has_start() ? escape(shown_start(v, bytes)) : "") +
                    "</td><td>" + escape(range_text(v)) + "</td><td>" + std::string(to_string(v.variability)) +
                    "</td><td>" + escape(v.description) + "</td></tr>\n";
        }
        if (rows.empty()) continue;
        html += std::string("<h2>") + title +
                "</h2>\n<table>\n<tr><th>name</th><th>type</th><th>unit</th><th>start</th><th>range</th>"
                "<th>variability</th><th>description</th></tr>\n" +
                rows + "</table>\n";
    }
    html += "</body>\n</html>\n";
    return html;
}

}  // namespace fmu
