// Small blocks with known closed-form behaviour, to test the runtime on its own.
#pragma once

#include <cstdint>

#include "fmu/block.hpp"

namespace fmu_test {

// A ball dropped from h0 under gravity g, bouncing with restitution e: a state event at h = 0.
// Closed form: first impact at t1 = sqrt(2 h0 / g) with speed g t1; after it the speed is e g t1.
// A choice (an FMI Enumeration): what the ball is made of; values as the model description gives them.
enum class BallMaterial : std::int32_t { rubber = 1, steel = 2 };

struct BallData {
    double g = 9.81;
    double e = 0.8;
    double h0 = 1.0;
    double drag = 0.0;  // tunable, for the roll-back test of validate()
    std::int32_t max_bounces = 1000;
    bool enabled = true;
    fmu::FixedString<15> label = "ball";
    BallMaterial material = BallMaterial::rubber;
    double u = 0.0;  // an input the output passes through
    double h = 1.0, v = 0.0;
    double der_h = 0.0, der_v = 0.0;
    double y = 0.0;
    std::int32_t bounces = 0;
    double next_tick = 0.0;  // a periodic time event every 0.25 s counted in ticks
    std::int32_t ticks = 0;
};

class Ball : public fmu::Block<Ball, BallData> {
public:
    static void declare(fmu::Table<BallData>& t) {
        t.parameter("g", &BallData::g, "m/s2", "Gravity").min(0.0);
        t.parameter("e", &BallData::e, "1", "Restitution").range(0.0, 1.0);
        t.parameter("h0", &BallData::h0, "m", "Initial height").min(0.0);
        t.parameter("drag", &BallData::drag, "1/s", "Linear drag").range(0.0, 10.0).tunable();
        t.parameter("max_bounces", &BallData::max_bounces, "", "Stop after this many").range(1, 1000000);
        t.parameter("enabled", &BallData::enabled, "", "Gravity on");
        t.parameter("label", &BallData::label, "", "A name");
        t.choice("material", &BallData::material, {{"rubber", BallMaterial::rubber}, {"steel", BallMaterial::steel}},
                 "What the ball is made of");
        t.input("u", &BallData::u, "1", "Pass-through input");
        auto h = t.state("h", &BallData::h, &BallData::der_h, "m", "Height").calculated_start();
        t.state("v", &BallData::v, &BallData::der_v, "m/s", "Velocity").derivative_depends_on({"v"});
        h.derivative_depends_on({"v"});  // v is declared after h: a handle can be refined later
        t.output("y", &BallData::y, "1", "Equals u").depends_on({"u"});
        t.output("bounces", &BallData::bounces, "", "Bounces so far").depends_on({});
        t.output("ticks", &BallData::ticks, "", "Time events so far").depends_on({});
    }
    static fmu::ModelInfo describe() {
        fmu::ModelInfo info;
        info.model_identifier = "test_ball";
        info.model_name = "test_ball";
        info.description = "Test ball";
        return info;
    }
    void initialize(double t) override {
        auto& d = data();
        d.h = d.h0;
        d.bounces = 0;
        d.ticks = 0;
        d.next_tick = t + 0.25;
    }
    void evaluate(double) override {
        auto& d = data();
        d.der_h = d.v;
        d.der_v = (d.enabled ? -d.g : 0.0) - d.drag * d.v;
        d.y = d.u;
    }
    std::size_t event_indicator_count() const override { return 1; }
    void event_indicators(double, std::span<double> z) override { z[0] = data().h; }
    fmu::EventUpdate event_update(double t, bool time_event_due) override {
        auto& d = data();
        fmu::EventUpdate r;
        if (time_event_due && fmu::reached(t, d.next_tick)) {
            ++d.ticks;
            d.next_tick += 0.25;
        }
        if (d.h <= 0.0 && d.v < 0.0) {
            d.h = 0.0;
            d.v = -d.e * d.v;
            ++d.bounces;
            r.states_changed = true;
            r.terminate = d.bounces >= d.max_bounces;
        }
        return r;
    }
    double next_time_event() const override { return data().next_tick; }
    void validate() const override {
        if (data().drag > 5.0 && data().e > 0.9) throw fmu::Error("drag > 5 needs e <= 0.9");
    }
};

// No continuous states: an indicator that crosses zero at t = crossing (located by bisection).
struct ClockData {
    double crossing = 0.35;
    std::int32_t crossings = 0;
};

class Clock : public fmu::Block<Clock, ClockData> {
public:
    static void declare(fmu::Table<ClockData>& t) {
        t.parameter("crossing", &ClockData::crossing, "s", "When the indicator crosses zero");
        t.output("crossings", &ClockData::crossings, "", "Crossings so far").depends_on({});
    }
    static fmu::ModelInfo describe() {
        fmu::ModelInfo info;
        info.model_identifier = "clock";
        info.model_name = "clock";
        info.description = "Test clock";
        return info;
    }
    std::size_t event_indicator_count() const override { return 1; }
    void event_indicators(double t, std::span<double> z) override { z[0] = t - data().crossing; }
    fmu::EventUpdate event_update(double, bool) override {
        ++data().crossings;
        return {};
    }
};

}  // namespace fmu_test
