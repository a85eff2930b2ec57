// The results table: one CSV row per run (run index, every drawn value, every metric, wall time,
// status, message). Rows are appended as runs finish, each flushed and checked, so a campaign killed
// at any moment keeps every finished run; at the end the table is rewritten in run order. --resume
// reads it back, drops a last row cut short by the kill and runs only the runs it lacks.
#pragma once

#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "campaign_spec.hpp"

namespace campaign {

struct RunResult {
    long index = 0;
    std::vector<std::string> draw_cells, metric_cells;
    double wall_time = 0.0;
    std::string status;   // ok, stopped (a component ended the run early), failed
    std::string message;  // why it failed or stopped
};

std::vector<std::string> table_header(const CampaignSpec& spec);
std::string format_row(const RunResult& result);  // no line end

// RFC 4180 cells: quoted when they hold a comma, a quote or a line end (line ends become spaces).
std::string csv_cell(const std::string& text);
std::vector<std::string> split_csv_line(const std::string& line);

// Column positions shared by the readers of a table.
inline constexpr std::size_t run_column = 0;
// From the end of a row: wall_time, status, message.
inline constexpr std::size_t trailing_columns = 3;

class ResultsWriter {
public:
    // A new table (refuses to replace an existing file) or, with `append`, an existing one.
    ResultsWriter(const std::filesystem::path& file, const std::vector<std::string>& header, bool append);
    ~ResultsWriter();
    ResultsWriter(const ResultsWriter&) = delete;
    ResultsWriter& operator=(const ResultsWriter&) = delete;
    void append(const std::string& row);  // written, flushed and checked before it returns

private:
    void write(const std::string& text);
    std::filesystem::path file_;
    std::FILE* out_ = nullptr;
};

// Rows of an existing table by run index, checked against the header this spec writes. A last line
// without its line end (the row being written when the campaign was killed) is cut off the file.
std::map<long, std::string> read_results(const std::filesystem::path& file, const std::vector<std::string>& header,
                                         long runs);

// The whole table in run order, through a temporary file renamed over it.
void write_sorted(const std::filesystem::path& file, const std::vector<std::string>& header,
                  const std::map<long, std::string>& rows);

}  // namespace campaign
