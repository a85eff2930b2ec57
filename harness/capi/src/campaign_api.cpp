// pvatt_campaign_run: a Monte-Carlo campaign through the campaign library, as `cosim campaign`.
#include <cmath>
#include <sstream>

#include "campaign_command.hpp"
#include "campaign_spec.hpp"
#include "capi_error.hpp"
#include "capi_handles.hpp"

using namespace pvatt_capi;

extern "C" {

void pvatt_campaign_options_init(pvatt_campaign_options* options) {
    if (!options) return;
    options->runs = 0;
    options->stop_time = NAN;
    options->output_dir = nullptr;
    options->figures = 0;
    options->resume = 0;
}

pvatt_status pvatt_campaign_run(const char* spec, const pvatt_campaign_options* options, const char* const* settings,
                                size_t setting_count, const char* const* fmu_dirs, size_t fmu_dir_count,
                                char* table_path, size_t size, size_t* needed) {
    return guarded([&] {
        campaign::CampaignOptions o;
        o.spec = required(spec, "spec");
        if (setting_count) required(settings, "settings");
        for (std::size_t i = 0; i < setting_count; ++i) o.settings.emplace_back(required(settings[i], "settings[i]"));
        if (fmu_dir_count) required(fmu_dirs, "fmu_dirs");
        for (std::size_t i = 0; i < fmu_dir_count; ++i) o.fmu_dirs.emplace_back(required(fmu_dirs[i], "fmu_dirs[i]"));
        o.figures = false;
        o.progress = false;
        if (options) {
            if (options->runs > 0) o.runs = options->runs;
            if (!std::isnan(options->stop_time)) o.stop_time = options->stop_time;
            if (options->output_dir) o.output = options->output_dir;
            o.figures = options->figures != 0;
            o.resume = options->resume != 0;
        }
        // Where the table goes: the option, else the spec's output folder (as the command decides it).
        const auto output = o.output ? *o.output : campaign::read_spec(o.spec).output;
        BlockingCall blocking;
        std::ostringstream report;  // the command's summary lines: the table holds the results
        campaign::run_campaign(o, report);
        copy_text((output / "results.csv").string(), table_path, size, needed);
    });
}

}  // extern "C"
