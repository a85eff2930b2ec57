// SI exponents of the units blocks use. "X/s" of any listed unit X is derived (for derivatives).
#include "fmu/units.hpp"

#include <array>

namespace fmu {

namespace {

constexpr std::array<UnitDefinition, 33> units{{
    {.name = "1"},
    {.name = "s", .s = 1},
    {.name = "Hz", .s = -1},
    {.name = "m", .m = 1},
    {.name = "m/s2", .m = 1, .s = -2},
    {.name = "rad", .rad = 1},
    {.name = "deg", .rad = 1, .factor = 0.017453292519943295},
    {.name = "rad/s", .s = -1, .rad = 1},
    {.name = "V", .kg = 1, .m = 2, .s = -3, .A = -1},
    {.name = "A", .A = 1},
    {.name = "W", .kg = 1, .m = 2, .s = -3},
    {.name = "W/m2", .kg = 1, .s = -3},
    {.name = "Ohm", .kg = 1, .m = 2, .s = -3, .A = -2},
    {.name = "F", .kg = -1, .m = -2, .s = 4, .A = 2},
    {.name = "C", .s = 1, .A = 1},
    {.name = "A.h", .s = 1, .A = 1, .factor = 3600.0},
    {.name = "T", .kg = 1, .s = -2, .A = -1},
    {.name = "V/T", .m = 2, .s = -1},
    {.name = "K", .K = 1},
    {.name = "degC", .K = 1, .offset = 273.15},
    {.name = "1/K", .K = -1},
    {.name = "kg.m2", .kg = 1, .m = 2},
    {.name = "V/A", .kg = 1, .m = 2, .s = -3, .A = -2},
    {.name = "%/V", .kg = -1, .m = -2, .s = 3, .A = 1, .factor = 0.01},
    {.name = "1/V", .kg = -1, .m = -2, .s = 3, .A = 1},
    {.name = "V/K", .kg = 1, .m = 2, .s = -3, .A = -1, .K = -1},
    {.name = "J/(m2.K)", .kg = 1, .s = -2, .K = -1},          // areal heat capacity
    {.name = "W/(m2.K)", .kg = 1, .s = -3, .K = -1},          // areal thermal conductance
    {.name = "J/K", .kg = 1, .m = 2, .s = -2, .K = -1},       // heat capacity
    {.name = "W/K", .kg = 1, .m = 2, .s = -3, .K = -1},       // thermal conductance
    {.name = "A.m2", .m = 2, .A = 1},                         // magnetic dipole moment
    {.name = "N.m", .kg = 1, .m = 2, .s = -2},                // torque
    {.name = "1/year", .s = -1, .factor = 1.0 / 31557600.0},  // a fraction per Julian year (a degradation)
}};

}  // namespace

std::optional<UnitDefinition> find_unit(std::string_view name) {
    for (const auto& u : units)
        if (u.name == name) return u;
    constexpr std::string_view per_second = "/s";
    if (name.size() > per_second.size() && name.ends_with(per_second)) {
        auto base = find_unit(name.substr(0, name.size() - per_second.size()));
        if (!base || base->offset != 0.0) return std::nullopt;
        base->name = name;  // points into the caller's string: valid while the caller's name lives
        base->s -= 1;
        return base;
    }
    if (name == "1/s") return UnitDefinition{.name = name, .s = -1};
    return std::nullopt;
}

}  // namespace fmu
