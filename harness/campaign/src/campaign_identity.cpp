#include "campaign_identity.hpp"

#include <fstream>
#include <sstream>

#include "campaign_error.hpp"
#include "engine/system_description.hpp"
#include "engine/value_text.hpp"

namespace campaign {

namespace {

using cosim::format_real;

std::string join(const std::vector<std::string>& items) {
    std::string out;
    for (const auto& i : items) out += (out.empty() ? "" : " ") + i;
    return out;
}

// Everything a draw decides, on one line.
std::string draw_line(const Draw& d) {
    std::vector<std::string> values;
    for (const auto& v : d.values) values.push_back(v.text);
    std::vector<std::string> weights;
    for (double w : d.weights) weights.push_back(format_real(w));
    return "draw " + d.target + " kind " + std::to_string(static_cast<int>(d.kind)) + " min " + format_real(d.min) +
           " max " + format_real(d.max) + " mean " + format_real(d.mean) + " sd " + format_real(d.sd) + " values [" +
           join(values) + "] weights [" + join(weights) + "] epoch " + format_real(d.epoch_from) + " " +
           format_real(d.epoch_to) + (d.stream.empty() ? "" : " stream " + d.stream);
}

}  // namespace

std::string campaign_identity(const CampaignSetup& s) {
    std::ostringstream id;
    id << "system " << std::filesystem::absolute(s.spec.system).lexically_normal().string() << "\n";
    id << "start_time " << format_real(s.start_time) << "\nstop_time " << format_real(s.stop_time) << "\n";
    id << "output_interval " << format_real(s.output_interval) << "\ntolerance " << format_real(s.tolerance) << "\n";
    id << "seed " << s.spec.seed << "\npaired " << (s.spec.paired ? "true" : "false") << "\n";
    // A parameter file by its values (an edited file is another campaign).
    for (const auto& file : s.options.parameter_files) {
        id << "parameters " << std::filesystem::absolute(file).lexically_normal().string() << "\n";
        for (const auto& v : cosim::read_parameter_values(file).values)
            id << "parameter " << v.variable << "=" << v.value << " " << v.ssv_type << "\n";
    }
    for (const auto& setting : s.options.settings) id << "set " << setting << "\n";
    for (const auto& d : s.spec.draws) id << draw_line(d) << "\n";
    for (const auto& m : s.spec.metrics)
        id << "metric " << m.name << " kind " << static_cast<int>(m.kind) << " a " << m.a << " b " << m.b << " valid "
           << m.valid << " when " << m.when << " after " << format_real(m.after) << " stats [" << join(m.stats) << "]"
           << (m.condition_column.empty()
                   ? std::string()
                   : " condition " + m.condition_column + " " + m.condition_op + " " + format_real(m.condition_value))
           << (m.kind == MetricKind::detection
                   ? " words [" + join(m.words) + "] times [" + join(m.times) + "] period " + format_real(m.period) +
                         " within " + format_real(m.within)
                   : std::string())
           << (m.kind == MetricKind::normalized_error ? " covariance " + m.covariance : std::string()) << "\n";
    // The cases (only in a spec that has them: the identity of a spec without is as before).
    for (const auto& c : s.spec.cases) {
        id << "case " << c.name << (c.control ? " control" : "") << " onset " << c.onset << "\n";
        for (const auto& setting : c.settings) id << "case " << c.name << " set " << setting << "\n";
        for (const auto& e : c.expect) {
            std::vector<std::string> elements;
            for (long k : e.elements) elements.push_back(std::to_string(k));
            id << "case " << c.name << " expect " << e.words << " " << e.variable << " [" << join(elements) << "]\n";
        }
        for (const auto& d : c.draws) id << "case " << c.name << " " << draw_line(d) << "\n";
        if (!c.observable.column.empty())
            id << "case " << c.name << " observable " << c.observable.column
               << (c.observable.above ? " above " : " below ") << format_real(c.observable.threshold) << "\n";
    }
    return id.str();
}

void record_identity(const std::filesystem::path& dir, const std::string& identity, bool resume) {
    const auto file = dir / "campaign.txt";
    // A table without its identity was made by something else (or its campaign.txt lost): resuming it
    // would add rows drawn under another seed or other settings to it.
    if (resume && !std::filesystem::exists(file))
        throw CampaignError("--resume: " + dir.string() + " has a results table but no " + file.filename().string() +
                            " saying which campaign made it: refusing to add rows to it (use another --output)");
    if (resume) {
        std::ifstream in(file);
        std::stringstream text;
        text << in.rdbuf();
        if (!in && !in.eof()) throw CampaignError("--resume: cannot read " + file.string());
        if (text.str() == identity) return;
        std::istringstream was(text.str()), is(identity);
        std::string a, b;
        while (std::getline(was, a) && std::getline(is, b) && a == b) {}
        throw CampaignError("--resume: the campaign in " + dir.string() + " was run with other settings (" +
                            file.string() + " has '" + a + "', this invocation '" + b + "'): use another --output");
    }
    const auto temporary = std::filesystem::path(file.string() + ".writing");
    {
        std::ofstream out(temporary);
        out << identity;
        out.close();
        if (!out) throw CampaignError("cannot write " + temporary.string());
    }
    std::filesystem::rename(temporary, file);
}

}  // namespace campaign
