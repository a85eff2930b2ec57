// Prints SGP4 states for the comparison with an independent implementation (compare_with_python_sgp4.py):
//   orbit_sgp4_states <double|float> "<line 1>" "<line 2>"  < minutes, one per line
// writes one line per time: minutes, status code, position (km) and velocity (km/s) in TEME.
// Exit status 2 with the parser's message on stderr when the set is refused.
#include <cstdio>
#include <cstring>
#include <exception>

#include "orbit/sgp4.hpp"
#include "orbit/tle.hpp"

namespace {
template <typename T>
int print_states(const orbit::Tle& tle) {
    orbit::Sgp4<T> sgp4;
    const orbit::Sgp4Status init = sgp4.initialize(tle.mean_elements<T>());
    double minutes = 0.0;
    while (std::scanf("%lf", &minutes) == 1) {
        orbit::OrbitState<T> s;
        const orbit::Sgp4Status status =
            init == orbit::Sgp4Status::ok ? sgp4.propagate(static_cast<T>(minutes), s) : init;
        std::printf("%.17g %d %.17g %.17g %.17g %.17g %.17g %.17g\n", minutes, static_cast<int>(status),
                    static_cast<double>(s.position_km.x()), static_cast<double>(s.position_km.y()),
                    static_cast<double>(s.position_km.z()), static_cast<double>(s.velocity_km_s.x()),
                    static_cast<double>(s.velocity_km_s.y()), static_cast<double>(s.velocity_km_s.z()));
    }
    return 0;
}
}  // namespace

int main(int argc, char** argv) {
    if (argc != 4 || (std::strcmp(argv[1], "double") != 0 && std::strcmp(argv[1], "float") != 0)) {
        std::fprintf(stderr, "usage: orbit_sgp4_states <double|float> \"<line 1>\" \"<line 2>\" < minutes\n");
        return 1;
    }
    try {
        const orbit::Tle tle = orbit::parse_tle(argv[2], argv[3]);
        return std::strcmp(argv[1], "double") == 0 ? print_states<double>(tle) : print_states<float>(tle);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 2;
    }
}
