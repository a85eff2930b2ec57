// The values one run draws, from the campaign's base seed and the run's index alone: every draw has
// its own generator seeded from (seed, index, target name), so a run can be replayed by itself, and
// adding, removing or reordering draws changes no other draw. Grid draws are not random: the run
// index walks their Cartesian product, the first grid draw varying fastest.
#pragma once

#include <cstdint>
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
// Combinations of the grid draws (1 when there are none).
long grid_size(const CampaignSpec& spec);

RunDraws draw_run(const CampaignSpec& spec, long index);

// The generator seed of one draw of one run (exposed for the tests of independence).
std::uint64_t stream_seed(std::uint64_t base_seed, std::uint64_t unit, const std::string& target);

}  // namespace campaign
