// A campaign's results table read back to judge its aims (pvatt_campaign_aims, a file anyone could have
// edited): any bytes give the aims' report, its JSON and its text, or a CampaignError; the spec below has
// each kind of aim, a skip_empty one and a choice of names to judge per kind of scene.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "aims.hpp"
#include "campaign_error.hpp"
#include "campaign_spec.hpp"
#include "summary.hpp"

namespace {

const campaign::CampaignSpec& spec() {
    static const campaign::CampaignSpec s = campaign::parse_spec(R"(system = "sys.ssd"
runs = 4
seed = 1
[[draw]]
kind = "choice"
target = "env.orbit_class"
values = ["polar", "iss"]
[[metric]]
name = "err"
kind = "quaternion_angle"
a = "env.q_true"
b = "est.q_est"
[[aim]]
column = "err.p95"
below = 1.0
[[aim]]
column = "err.mean"
within = [0.5, 1.5]
skip_empty = true
[[aim]]
column = "err.max"
at_least = 2
)",
                                                                 "/fuzz/spec.toml");
    return s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const campaign::ResultRows table = campaign::parse_table(text, "fuzz.csv");
        const auto report = campaign::judge_aims(spec(), table);
        const auto by = campaign::judge_aims_by_category(spec(), table);
        (void)campaign::aims_json(spec(), report, by);
        std::ostringstream out;
        campaign::print_aims(spec(), report, by, out);
        campaign::write_aims(out, spec(), report, by);
    } catch (const campaign::CampaignError&) {}
    return 0;
}
