// The values one run draws, from the campaign's base seed and the run's index alone: every draw has
// its own generator seeded from (seed, index, target name), so a run can be replayed by itself, and
// adding, removing or reordering draws changes no other draw. Grid draws are not random: the run
// index walks their Cartesian product, the first grid draw varying fastest. A spec's cases are walked the
// same way, before the grid draws: run k takes case k mod the number of cases.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "campaign_spec.hpp"

namespace campaign {

// A column of the results table holding a drawn value.
struct DrawColumn {
    std::string name;
    bool plotted = false;  // drawn quantities worth a figure (not the quaternion and vector components)
};

struct RunDraws {
    std::vector<std::string> settings;  // "component.variable=value", applied after the spec's [set]
    std::vector<std::string> cells;     // one per draw_columns() entry, as written in the table
};

std::vector<DrawColumn> draw_columns(const CampaignSpec& spec);
// The FMU variables a draw sets ("env.q0[1]", ...), to check them against the system before running.
std::vector<std::string> drawn_variables(const Draw& draw);
// Combinations of the cases and the grid draws (1 when there are none); the cases vary fastest.
long grid_size(const CampaignSpec& spec);
long case_count(const CampaignSpec& spec);  // 1 when the spec has no cases
// The case run `index` takes (none without cases): index mod the number of cases.
std::optional<std::size_t> case_of(const CampaignSpec& spec, long index);
// The run of the control case with the same scene and grid combination as run `index`, for a paired
// spec with a control case.
std::optional<long> paired_control(const CampaignSpec& spec, long index);

RunDraws draw_run(const CampaignSpec& spec, long index);

// The scenario's element set the epoch and orbit draws start from (Draw::base_elements): read from the
// system through `value_of` ("env.tle_elements[1]" -> its start value). Throws CampaignError when the system
// gives that set as tle_line1/2 text (the drawn numbers would not replace it) or has no such variables.
void read_scenario_base(CampaignSpec& spec,
                        const std::function<std::optional<std::string>(const std::string&)>& value_of);

// The generator seed of one draw of one run (exposed for the tests of independence).
std::uint64_t stream_seed(std::uint64_t base_seed, std::uint64_t unit, const std::string& target);

}  // namespace campaign
