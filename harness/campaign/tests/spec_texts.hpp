// What the campaign's tests share about specs: the error a spec text is refused with, the quick LEO spec
// (specs/leo_short.toml) as text with its system's path made absolute, to extend and write elsewhere, a scratch
// folder to write it in, and the options of a quiet campaign of a spec written there.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "campaign_command.hpp"
#include "campaign_error.hpp"
#include "campaign_spec.hpp"

namespace campaign_test {

// What parse_spec refuses the text with ("" when it reads it), the spec named /specs/test.toml.
inline std::string error_of(const std::string& text) {
    try {
        campaign::parse_spec(text, "/specs/test.toml");
    } catch (const campaign::CampaignError& e) {
        return e.what();
    }
    return "";
}

// specs/leo_short.toml with its system's path absolute (CAMPAIGN_TEST_SPECS): the text can go anywhere.
inline std::string leo_short_text() {
    std::ifstream in(std::string(CAMPAIGN_TEST_SPECS) + "/leo_short.toml");
    std::stringstream text;
    text << in.rdbuf();
    std::string spec = text.str();
    const std::string relative = "\"../../../systems/leo_orbit.ssd\"";
    spec.replace(spec.find(relative), relative.size(),
                 "\"" + std::string(CAMPAIGN_TEST_SPECS) + "/../../../systems/leo_orbit.ssd\"");
    return spec;
}

// A test's scratch folder, campaign_test_<name>_<pid> in the temporary directory: emptied, and created unless
// `create` is false (a campaign's output folder the campaign makes itself).
inline std::filesystem::path fresh_dir(const std::string& name, bool create = true) {
    const auto dir =
        std::filesystem::temp_directory_path() / ("campaign_test_" + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    if (create) std::filesystem::create_directories(dir);
    return dir;
}

// A campaign of `spec` into `output` on this build's FMUs, without progress lines or figures.
inline campaign::CampaignOptions quiet_options(const std::filesystem::path& spec, const std::filesystem::path& output) {
    campaign::CampaignOptions o;
    o.spec = spec;
    o.output = output;
    o.fmu_dirs = {PVATT_FMU_DIR};
    o.progress = false;
    o.figures = false;
    return o;
}

}  // namespace campaign_test
