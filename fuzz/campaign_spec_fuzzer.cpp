// The campaign spec reader (TOML from anyone's editor): any bytes give a CampaignSpec or a
// CampaignError, and a spec it accepts draws its first runs without leaving the doubles' arithmetic
// (overflowing spans, weights, grid sizes are the spec reader's to refuse).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>

#include "campaign_error.hpp"
#include "campaign_spec.hpp"
#include "draws.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const campaign::CampaignSpec spec = campaign::parse_spec(text, "/fuzz/spec.toml");
        (void)campaign::draw_columns(spec);
        for (long run = 0; run < std::min(spec.runs, 3L); ++run) (void)campaign::draw_run(spec, run);
    } catch (const campaign::CampaignError&) {}
    return 0;
}
