#include "fmi_loader/scalar_view.hpp"

#include <sstream>
#include <string>

#include "fmi_loader/loader_error.hpp"

namespace fmi_loader {

namespace {

// "x" with extents {2, 3} and flat offset 4 -> "x[2,2]" (row-major, 1-based as in structured names).
std::string element_name(const std::string& name, const std::vector<std::size_t>& extents, std::size_t offset) {
    std::vector<std::size_t> index(extents.size());
    for (std::size_t d = extents.size(); d-- > 0;) {
        index[d] = offset % extents[d] + 1;
        offset /= extents[d];
    }
    std::string out = name + "[";
    for (std::size_t d = 0; d < index.size(); ++d) out += (d ? "," : "") + std::to_string(index[d]);
    return out + "]";
}

// The start values of an array: FMI 3.0 lists them space-separated (String and Binary as <Start>
// children); one value stands for every element.
std::vector<std::string> element_starts(const ScalarVariable& v, std::size_t count) {
    std::vector<std::string> values = v.start_values;
    if (values.empty() && v.start) {
        std::istringstream in(*v.start);
        for (std::string token; in >> token;) values.push_back(token);
    }
    if (values.size() == 1 && count > 1) values.assign(count, values.front());
    if (!values.empty() && values.size() != count)
        throw LoaderError(LoaderErrc::xml_invalid, "variable '" + v.name + "' has " + std::to_string(count) +
                                                       " elements but " + std::to_string(values.size()) +
                                                       " start values");
    return values;
}

std::vector<std::size_t> expand(const std::vector<std::size_t>& indices, const ScalarView& view,
                                const ModelDescription& md) {
    std::vector<std::size_t> out;
    for (const auto i : indices) {
        const std::size_t first = view.first_element[i - 1];
        for (std::size_t k = 0; k < md.element_count(md.model_variables[i - 1]); ++k) out.push_back(first + k + 1);
    }
    return out;
}

std::vector<Unknown> expand(const std::vector<Unknown>& unknowns, const ScalarView& view, const ModelDescription& md) {
    std::vector<Unknown> out;
    for (const auto& u : unknowns) {
        const std::size_t first = view.first_element[u.index - 1];
        std::optional<std::vector<std::size_t>> deps;
        if (u.dependencies) deps = expand(*u.dependencies, view, md);
        for (std::size_t k = 0; k < md.element_count(md.model_variables[u.index - 1]); ++k)
            out.push_back({first + k + 1, deps, u.dependencies ? u.dependencies_kind : std::vector<std::string>{}});
    }
    return out;
}

}  // namespace

ScalarView scalar_view(const ModelDescription& md, const Limits& limits) {
    ScalarView view;
    view.description = md;
    auto& vars = view.description.model_variables;
    vars.clear();
    for (std::size_t i = 0; i < md.model_variables.size(); ++i) {
        const ScalarVariable& v = md.model_variables[i];
        const std::size_t count = md.element_count(v);
        view.first_element.push_back(vars.size());
        if (vars.size() + count > limits.max_variables)
            throw LoaderError(LoaderErrc::limit, "'" + md.model_name + "': more than the limit of " +
                                                     std::to_string(limits.max_variables) +
                                                     " scalar elements (max_variables)");
        const auto starts = v.dimensions.empty() ? std::vector<std::string>{} : element_starts(v, count);
        const auto extents = md.extents(v);
        for (std::size_t k = 0; k < count; ++k) {
            ScalarVariable e = v;
            e.dimensions.clear();
            e.start_values.clear();
            if (!v.dimensions.empty()) {
                e.name = element_name(v.name, extents, k);
                e.start = starts.empty() ? std::nullopt : std::optional<std::string>(starts[k]);
            }
            e.value_reference = static_cast<std::uint32_t>(vars.size());
            view.elements.push_back({v.value_reference, k, count, v.fmi3_type.value_or(Fmi3Type::float64), i});
            vars.push_back(std::move(e));
        }
    }
    // derivative: the element of the state with the same offset.
    for (std::size_t j = 0; j < vars.size(); ++j)
        if (vars[j].derivative)
            vars[j].derivative = view.first_element[*vars[j].derivative - 1] + view.elements[j].offset + 1;
    auto& s = view.description.model_structure;
    const auto& o = md.model_structure;
    s.outputs = expand(o.outputs, view, md);
    s.derivatives = expand(o.derivatives, view, md);
    s.initial_unknowns = expand(o.initial_unknowns, view, md);
    s.event_indicators = expand(o.event_indicators, view, md);
    s.clocked_states = expand(o.clocked_states, view, md);
    return view;
}

}  // namespace fmi_loader
