// pvatt_campaign_run: a Monte-Carlo campaign in the calling process, through the campaign library: the
// spec prepared, its runs done one after the other, one row each in the results table. What the
// command `cosim campaign` adds around that (MPI ranks, the folder lock, the summary and its figures,
// the replay of one run) stays with the command. pvatt_campaign_aims judges a written table by its spec's
// aims, with the same code and words as the command's end.
#include <cmath>
#include <sstream>

#include "aims.hpp"

#include "campaign_error.hpp"
#include "campaign_run.hpp"
#include "campaign_spec.hpp"
#include "capi_error.hpp"
#include "capi_handles.hpp"
#include "collector.hpp"
#include "drivers.hpp"
#include "engine/interrupt.hpp"
#include "results_table.hpp"
#include "summary.hpp"

using namespace pvatt_capi;

namespace {

std::filesystem::path run_campaign(const std::filesystem::path& spec_file, const pvatt_campaign_options* options,
                                   const std::vector<std::filesystem::path>& fmu_dirs,
                                   const std::vector<std::string>& settings) {
    campaign::CampaignSpec spec = campaign::read_spec(spec_file);
    bool resume = false;
    if (options) {
        if (options->runs > 0) {
            if (options->runs > campaign::max_runs)
                throw InvalidArgument("runs must be from 1 to " + std::to_string(campaign::max_runs));
            spec.runs = options->runs;
        }
        if (!std::isnan(options->stop_time)) spec.stop_time = options->stop_time;
        if (options->output_dir) spec.output = options->output_dir;
        resume = options->resume != 0;
    }
    const campaign::CampaignSetup setup = campaign::prepare(std::move(spec), fmu_dirs, settings);
    const auto& out = setup.spec.output;
    std::filesystem::create_directories(out);
    const auto table = out / "results.csv";
    const bool append = resume && std::filesystem::exists(table);
    if (!append && std::filesystem::exists(table))
        throw campaign::CampaignError(table.string() + " exists: resume that campaign, or give another output folder");
    const auto header = campaign::table_header(setup.spec);
    std::map<long, std::string> rows;
    if (append) rows = campaign::read_results(table, header, setup.spec.runs);
    {
        campaign::ResultsWriter writer(table, header, append);
        campaign::RunQueue to_do(setup.spec.runs, rows);
        campaign::Collector collector(writer, rows, to_do.size(), 1, campaign::Progress::none);
        campaign::run_sequential(setup, to_do, collector);
        collector.finish();
    }
    campaign::write_sorted(table, header, rows);
    return table;
}

}  // namespace

extern "C" {

void pvatt_campaign_options_init(pvatt_campaign_options* options) {
    if (!options) return;
    options->runs = 0;
    options->stop_time = NAN;
    options->output_dir = nullptr;
    options->resume = 0;
}

pvatt_status pvatt_campaign_run(const char* spec, const pvatt_campaign_options* options, const char* const* settings,
                                size_t setting_count, const char* const* fmu_dirs, size_t fmu_dir_count,
                                char* table_path, size_t size, size_t* needed) {
    return guarded([&] {
        refuse_in_callback("pvatt_campaign_run");
        const std::filesystem::path spec_file(required(spec, "spec"));
        std::vector<std::string> extra;
        if (setting_count) required(settings, "settings");
        for (std::size_t i = 0; i < setting_count; ++i) extra.emplace_back(required(settings[i], "settings[i]"));
        std::vector<std::filesystem::path> dirs;
        if (fmu_dir_count) required(fmu_dirs, "fmu_dirs");
        for (std::size_t i = 0; i < fmu_dir_count; ++i) dirs.emplace_back(required(fmu_dirs[i], "fmu_dirs[i]"));
        BlockingCall blocking;
        try {
            copy_text(run_campaign(spec_file, options, dirs, extra).string(), table_path, size, needed);
        } catch (const cosim::Interrupted&) {
            blocking.reported();
            throw;
        }
    });
}

pvatt_status pvatt_campaign_aims(const char* spec, const char* table, int as_text, char* buffer, size_t size,
                                 size_t* needed) {
    return guarded([&] {
        // The spec read for its aims and draws only: no FMU is loaded. A table without an aim's column (another
        // spec's) is refused by name.
        const campaign::CampaignSpec s = campaign::read_spec(required(spec, "spec"));
        const campaign::ResultRows rows = campaign::read_table(required(table, "table"));
        const campaign::AimsReport report = campaign::judge_aims(s, rows);
        const auto by_category = campaign::judge_aims_by_category(s, rows);
        std::string text;
        if (as_text) {
            std::ostringstream out;
            campaign::print_aims(s, report, by_category, out);
            text = out.str();
        } else {
            text = campaign::aims_json(s, report, by_category);
        }
        copy_text(text, buffer, size, needed);
    });
}

}  // extern "C"
