// Tiny blocks with closed-form behaviour for the master's tests: a gain (direct feedthrough) and an
// integrator (none). Units chosen so they connect in both directions.
#pragma once

#include <cstdint>

#include "fmu/block.hpp"

namespace cosim_test {

// The gain's sign: a choice (an FMI Enumeration), for the master's settings by item name or number.
enum class Sign : std::int32_t { plus = 1, minus = 2 };

struct GainData {
    double k = 2.0;
    Sign sign = Sign::plus;
    double u = 1.0;
    double y = 0.0;
};

class Gain : public fmu::Block<Gain, GainData> {
public:
    static void declare(fmu::Table<GainData>& t) {
        t.parameter("k", &GainData::k, "1", "Gain").tunable();
        t.choice("sign", &GainData::sign, {{"plus", Sign::plus}, {"minus", Sign::minus}}, "Sign of the gain");
        t.input("u", &GainData::u, "V", "Input");
        t.output("y", &GainData::y, "V", "k times u").depends_on({"u"});
    }
    static fmu::ModelInfo describe() {
        fmu::ModelInfo info;
        info.model_identifier = "test_gain";
        info.model_name = "test_gain";
        info.description = "y = k u";
        return info;
    }
    void evaluate(double) override { data().y = (data().sign == Sign::minus ? -1.0 : 1.0) * data().k * data().u; }
};

struct IntegratorData {
    double tau = 1.0;
    double u = 0.0;
    double x = 1.0, der_x = 0.0;
    double y = 0.0;
};

class Integrator : public fmu::Block<Integrator, IntegratorData> {
public:
    static void declare(fmu::Table<IntegratorData>& t) {
        t.parameter("tau", &IntegratorData::tau, "s", "Time constant").min(1e-6);
        t.input("u", &IntegratorData::u, "V", "Input");
        t.state("x", &IntegratorData::x, &IntegratorData::der_x, "V", "Integral of u / tau")
            .derivative_depends_on({"u"});
        t.output("y", &IntegratorData::y, "V", "Equals x").depends_on({"x"});
    }
    static fmu::ModelInfo describe() {
        fmu::ModelInfo info;
        info.model_identifier = "test_integrator";
        info.model_name = "test_integrator";
        info.description = "dx/dt = u / tau, y = x";
        return info;
    }
    void evaluate(double) override {
        auto& d = data();
        d.der_x = d.u / d.tau;
        d.y = d.x;
    }
};

}  // namespace cosim_test
