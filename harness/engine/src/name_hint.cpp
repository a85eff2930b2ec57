#include "engine/name_hint.hpp"

#include <algorithm>

namespace cosim {

namespace {

// Edit distance counting an insertion, deletion, substitution or swap of neighbours as one (optimal
// string alignment): "ets" is one edit from "est", as a typist sees it.
std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
        for (std::size_t j = 1; j <= b.size(); ++j) {
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

// "sun_body[2]" -> "sun_body"; a name without an index is its own base.
std::string_view base_name(std::string_view name) {
    const auto bracket = name.find('[');
    return bracket == std::string_view::npos ? name : name.substr(0, bracket);
}

}  // namespace

std::vector<std::string> closest_names(std::string_view name, const std::vector<std::string>& candidates) {
    const std::size_t limit = std::max<std::size_t>(1, name.size() / 3);
    std::vector<std::pair<std::size_t, std::string>> near;
    for (const auto& c : candidates) {
        const std::size_t d = edit_distance(name, c);
        if (d == 0 || d > limit) continue;
        if (std::any_of(near.begin(), near.end(), [&](const auto& n) { return n.second == c; })) continue;
        near.emplace_back(d, c);
    }
    std::stable_sort(near.begin(), near.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<std::string> out;
    // The closest only: 'mag_bdy[1]' is one edit from mag_body[1] and two from mag_body[2].
    for (std::size_t i = 0; i < near.size() && i < 3 && near[i].first == near.front().first; ++i)
        out.push_back(near[i].second);
    return out;
}

std::string name_hint(std::string_view name, const std::vector<std::string>& candidates) {
    // An array's base name: its first and last elements.
    const std::string prefix = std::string(name) + "[";
    std::vector<std::string> elements;
    for (const auto& c : candidates)
        if (c.starts_with(prefix)) elements.push_back(c);
    if (!elements.empty())
        return elements.size() == 1 ? " (an array: " + elements.front() + ")"
                                    : " (an array: " + elements.front() + " .. " + elements.back() + ")";
    const auto near = closest_names(name, candidates);
    if (near.empty()) return "";
    std::string hint = " (did you mean ";
    for (std::size_t i = 0; i < near.size(); ++i)
        hint += (i == 0 ? "" : i + 1 == near.size() ? " or " : ", ") + ("'" + near[i] + "'");
    return hint + "?)";
}

std::string unknown_variable_message(const fmi_loader::ModelDescription& md, const std::string& owner,
                                     std::string_view name) {
    std::vector<std::string> names;
    names.reserve(md.model_variables.size() * 2);
    for (const auto& v : md.model_variables) names.push_back(v.name);
    std::string hint = name_hint(name, names);
    if (hint.empty()) {
        // A misspelt array ("sun_bdy[1]" or "sun_bdy"): compare base names, and keep the index asked for.
        std::vector<std::string> bases;
        for (const auto& v : md.model_variables) bases.emplace_back(base_name(v.name));
        const auto base = base_name(name);
        auto near = closest_names(base, bases);
        if (!near.empty()) {
            const std::string index(name.substr(base.size()));
            hint = " (did you mean ";
            for (std::size_t i = 0; i < near.size(); ++i)
                hint += (i == 0 ? "" : i + 1 == near.size() ? " or " : ", ") + ("'" + near[i] + index + "'");
            hint += "?)";
        }
    }
    return owner + ": no variable named '" + std::string(name) + "'" + hint;
}

}  // namespace cosim
