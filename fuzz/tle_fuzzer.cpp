// orbit::parse_tle on arbitrary text (an element set comes from outside: a parameter, an uplink): the
// input up to its first newline is line 1, the rest line 2. A refusal must be a TleError; an accepted
// set must propagate without a crash and give either an SGP4 error code or a finite state.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "orbit/frames.hpp"
#include "orbit/tle.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const std::size_t newline = text.find('\n');
    const std::string_view line1 = text.substr(0, newline);
    const std::string_view line2 = newline == std::string_view::npos ? std::string_view() : text.substr(newline + 1);
    orbit::Tle tle;
    try {
        tle = orbit::parse_tle(line1, line2);
    } catch (const orbit::TleError&) {
        return 0;
    }
    orbit::Sgp4<double> sgp4;
    if (sgp4.initialize(tle.mean_elements<double>()) != orbit::Sgp4Status::ok) std::abort();  // parse_tle checked it
    for (double minutes : {0.0, 90.0, 1440.0, -1440.0}) {
        orbit::OrbitState<double> s;
        if (sgp4.propagate(minutes, s) != orbit::Sgp4Status::ok) continue;
        const orbit::OrbitState<double> j2000 = orbit::teme_to_j2000(s, orbit::julian_centuries(tle.epoch_jd_utc));
        if (!std::isfinite(j2000.position_km.norm()) || !std::isfinite(j2000.velocity_km_s.norm())) std::abort();
    }
    return 0;
}
