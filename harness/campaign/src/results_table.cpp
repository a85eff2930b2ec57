#include "results_table.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>

#include "campaign_error.hpp"
#include "draws.hpp"
#include "engine/value_text.hpp"
#include "metric_observer.hpp"

namespace campaign {

std::vector<std::string> table_header(const CampaignSpec& spec) {
    std::vector<std::string> h = {"run"};
    for (const auto& c : draw_columns(spec)) h.push_back(c.name);
    for (const auto& c : metric_columns(spec)) h.push_back(c);
    h.insert(h.end(), {"wall_time", "status", "message"});
    return h;
}

std::string csv_cell(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string out = "\"";
    for (char c : text) {
        if (c == '"')
            out += "\"\"";
        else if (c == '\n' || c == '\r')
            out += ' ';
        else
            out += c;
    }
    return out + "\"";
}

std::vector<std::string> split_csv_line(const std::string& line) {
    std::vector<std::string> cells(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                cells.back() += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                cells.back() += c;
            }
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            cells.emplace_back();
        } else {
            cells.back() += c;
        }
    }
    return cells;
}

namespace {

std::string join(const std::vector<std::string>& cells) {
    std::string out;
    for (std::size_t i = 0; i < cells.size(); ++i) out += (i ? "," : "") + csv_cell(cells[i]);
    return out;
}

}  // namespace

std::string format_row(const RunResult& r) {
    std::vector<std::string> cells = {std::to_string(r.index)};
    cells.insert(cells.end(), r.draw_cells.begin(), r.draw_cells.end());
    cells.insert(cells.end(), r.metric_cells.begin(), r.metric_cells.end());
    cells.insert(cells.end(), {cosim::format_real(r.wall_time), r.status, r.message});
    return join(cells);
}

ResultsWriter::ResultsWriter(const std::filesystem::path& file, const std::vector<std::string>& header, bool append)
    : file_(file) {
    if (!append && std::filesystem::exists(file))
        throw CampaignError(file.string() + " exists: give --resume to continue that campaign, or another --output");
    out_ = std::fopen(file.c_str(), append ? "a" : "w");
    if (!out_) throw CampaignError("cannot write " + file.string() + ": " + std::strerror(errno));
    if (!append) write(join(header) + "\n");
}

ResultsWriter::~ResultsWriter() {
    if (out_) std::fclose(out_);
}

void ResultsWriter::write(const std::string& text) {
    if (std::fwrite(text.data(), 1, text.size(), out_) != text.size() || std::fflush(out_) != 0)
        throw CampaignError("cannot write " + file_.string() + ": " + std::strerror(errno));
}

void ResultsWriter::append(const std::string& row) {
    write(row + "\n");
}

std::map<long, std::string> read_results(const std::filesystem::path& file, const std::vector<std::string>& header,
                                         long runs) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw CampaignError("--resume: cannot read " + file.string());
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw CampaignError("--resume: cannot read " + file.string());
    const auto cut = text.rfind('\n');
    if (cut == std::string::npos) throw CampaignError("--resume: " + file.string() + " has no complete header line");
    if (cut + 1 != text.size()) {
        // The row being written when the campaign was killed: that run is done again.
        text.resize(cut + 1);
        std::filesystem::resize_file(file, text.size());
    }
    std::map<long, std::string> rows;
    std::size_t start = 0, line_number = 0;
    while (start < text.size()) {
        const auto end = text.find('\n', start);
        const std::string line = text.substr(start, end - start);
        start = end + 1;
        ++line_number;
        const auto cells = split_csv_line(line);
        const std::string where = file.string() + ":" + std::to_string(line_number) + ": ";
        if (line_number == 1) {
            if (cells != header)
                throw CampaignError(where +
                                    "the header differs from what this spec writes (another spec or version): "
                                    "use another --output");
            continue;
        }
        if (cells.size() != header.size())
            throw CampaignError(where + "a row of " + std::to_string(cells.size()) + " cells where the header has " +
                                std::to_string(header.size()));
        long index = -1;
        try {
            index = static_cast<long>(cosim::parse_integer(cells[run_column], "run index"));
        } catch (const std::exception& e) {
            throw CampaignError(where + e.what());
        }
        if (index < 0) throw CampaignError(where + "negative run index");
        if (index >= runs)
            throw CampaignError(where + "run " + std::to_string(index) + " is beyond this campaign's " +
                                std::to_string(runs) + " runs (--runs smaller than when it was written?)");
        if (!rows.emplace(index, line).second)
            throw CampaignError(where + "run " + std::to_string(index) + " appears twice");
    }
    return rows;
}

void write_sorted(const std::filesystem::path& file, const std::vector<std::string>& header,
                  const std::map<long, std::string>& rows) {
    const auto temporary = std::filesystem::path(file.string() + ".sorting");
    {
        std::FILE* out = std::fopen(temporary.c_str(), "w");
        if (!out) throw CampaignError("cannot write " + temporary.string() + ": " + std::strerror(errno));
        std::string text = join(header) + "\n";
        for (const auto& [index, row] : rows) text += row + "\n";
        const bool ok = std::fwrite(text.data(), 1, text.size(), out) == text.size();
        if (std::fclose(out) != 0 || !ok)
            throw CampaignError("cannot write " + temporary.string() + ": " + std::strerror(errno));
    }
    std::filesystem::rename(temporary, file);
}

}  // namespace campaign
