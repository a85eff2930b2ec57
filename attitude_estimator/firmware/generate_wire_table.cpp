// Writes estimator_wire_table.hpp for the firmware: attitude_estimator.fmu's inputs, outputs and
// (non-String) parameters in value-reference order — the order the bridge's frames carry them — as
// switch statements over the fields of EstimatorData, with each parameter's range and items. The block's
// variable table (estimator_block.cpp) stays the one place that declares them: this program reads it
// through the block linked in (fmu::make_model), and the compiler checks every field it names.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "fmu/model.hpp"
#include "fmu/variable.hpp"

namespace {

// "i_sc_norm[2]" -> "d.i_sc_norm[1]"; "sample_period" -> "d.sample_period".
std::string field(const fmu::Variable& v) {
    const auto open = v.name.find('[');
    if (open == std::string::npos) return "d." + v.name;
    const int index = std::stoi(v.name.substr(open + 1));
    return "d." + v.base_name + "[" + std::to_string(index - 1) + "]";
}

std::string number(double x) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    return buf;
}

std::vector<const fmu::Variable*> of(const fmu::TableBase& table, fmu::Causality c) {
    std::vector<const fmu::Variable*> out;
    for (const auto& v : table.variables())
        if (v.causality == c && v.type != fmu::ValueType::String) out.push_back(&v);
    std::sort(out.begin(), out.end(), [](auto* a, auto* b) { return a->value_reference < b->value_reference; });
    return out;
}

// The statement that stores x (a double from the wire, already checked) into v's field.
std::string store(const fmu::Variable& v) {
    switch (v.type) {
        case fmu::ValueType::Real:
            return field(v) + " = x;";
        case fmu::ValueType::Integer:
            return field(v) + " = static_cast<std::int32_t>(std::lround(x));";
        case fmu::ValueType::Enumeration:
            return field(v) + " = static_cast<decltype(" + field(v) + ")>(std::lround(x));";
        case fmu::ValueType::Boolean:
            return field(v) + " = x != 0.0;";
        case fmu::ValueType::String:
            break;
    }
    return "";
}

// The condition under which parameter v takes the value x.
std::string accepts(const fmu::Variable& v) {
    std::string c = "std::isfinite(x)";
    if (v.min) c += " && x >= " + number(*v.min);
    if (v.max) c += " && x <= " + number(*v.max);
    if (v.type == fmu::ValueType::Enumeration) {
        std::string items;
        for (const auto& item : v.items)
            items += (items.empty() ? "" : " || ") + std::string("x == ") + std::to_string(item.value);
        c += " && (" + items + ")";
    }
    if (v.type == fmu::ValueType::Integer) c += " && x == std::round(x) && std::abs(x) < 2147483648.0";
    return c;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: " << argv[0] << " OUTPUT.hpp\n";
        return 2;
    }
    const auto model = fmu::make_model();
    const auto& table = model->table();
    const auto inputs = of(table, fmu::Causality::input), outputs = of(table, fmu::Causality::output),
               parameters = of(table, fmu::Causality::parameter);
    std::ostringstream h;
    h << "// Generated at build time by attitude_estimator/firmware/generate_wire_table.cpp from the variable table\n"
         "// of "
      << model->info().model_identifier
      << ".fmu: do not edit. Inputs, outputs and non-String parameters in\n"
         "// value-reference order, the order of the hardware bridge's frames (protocol/README.md).\n"
         "#pragma once\n\n#include <cmath>\n#include <cstddef>\n#include <cstdint>\n\n"
         "#include \"attitude_estimator/estimator_data.hpp\"\n\n"
         "namespace attitude_estimator::wire {\n\n"
      << "inline constexpr std::size_t kInputCount = " << inputs.size() << ";\n"
      << "inline constexpr std::size_t kOutputCount = " << outputs.size() << ";\n"
      << "inline constexpr std::size_t kParameterCount = " << parameters.size() << ";\n\n";
    h << "// Input i of a request frame into its field.\ninline void set_input(EstimatorData& d, std::size_t i, double "
         "x) {\n"
         "    switch (i) {\n";
    for (std::size_t i = 0; i < inputs.size(); ++i)
        h << "        case " << i << ":  // " << inputs[i]->name << "\n            " << store(*inputs[i])
          << "\n            break;\n";
    h << "        default:\n            break;\n    }\n}\n\n";
    h << "// Output i of a reply frame.\ninline double output(const EstimatorData& d, std::size_t i) {\n    switch (i) "
         "{\n";
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const auto& v = *outputs[i];
        const std::string value = v.type == fmu::ValueType::Boolean ? "(" + field(v) + " ? 1.0 : 0.0)"
                                                                    : "static_cast<double>(" + field(v) + ")";
        h << "        case " << i << ":  // " << v.name << "\n            return " << value << ";\n";
    }
    h << "        default:\n            return 0.0;\n    }\n}\n\n";
    h << "// Whether parameter i takes the value x (finite, in its declared range, an item of its Enumeration).\n"
         "inline bool parameter_accepts(std::size_t i, double x) {\n    switch (i) {\n";
    for (std::size_t i = 0; i < parameters.size(); ++i)
        h << "        case " << i << ":  // " << parameters[i]->name << "\n            return "
          << accepts(*parameters[i]) << ";\n";
    h << "        default:\n            return false;\n    }\n}\n\n";
    h << "// Parameter i of a configure frame into its field (checked with parameter_accepts first).\n"
         "inline void set_parameter(EstimatorData& d, std::size_t i, double x) {\n    switch (i) {\n";
    for (std::size_t i = 0; i < parameters.size(); ++i)
        h << "        case " << i << ":  // " << parameters[i]->name << "\n            " << store(*parameters[i])
          << "\n            break;\n";
    h << "        default:\n            break;\n    }\n}\n\n";
    h << "// Parameter i's value as a configure frame carries it (the bench builds its configurations with it).\n"
         "inline double parameter(const EstimatorData& d, std::size_t i) {\n    switch (i) {\n";
    for (std::size_t i = 0; i < parameters.size(); ++i) {
        const auto& v = *parameters[i];
        const std::string value = v.type == fmu::ValueType::Boolean ? "(" + field(v) + " ? 1.0 : 0.0)"
                                                                    : "static_cast<double>(" + field(v) + ")";
        h << "        case " << i << ":  // " << v.name << "\n            return " << value << ";\n";
    }
    h << "        default:\n            return 0.0;\n    }\n}\n\n";
    h << "// Indices of the parameters the firmware checks by name.\n";
    for (std::size_t i = 0; i < parameters.size(); ++i) {
        const auto& n = parameters[i]->name;
        if (n == "precision" || n == "spin_window")
            h << "inline constexpr std::size_t kParameter_" << n << " = " << i << ";\n";
    }
    h << "\n}  // namespace attitude_estimator::wire\n";
    std::ofstream out(argv[1]);
    out << h.str();
    out.close();
    if (!out) {
        std::cerr << "cannot write " << argv[1] << "\n";
        return 1;
    }
    return 0;
}
