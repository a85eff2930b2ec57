// A sampled block like the estimator, small enough to check by hand: every sample_period (a time
// event, first at the start time) it latches y[i] = k * u[i] and counts the samples; in between its
// outputs hold. The bridge tests run it as an FMU and behind the board emulator.
#include <array>
#include <cstdint>

#include "fmu/block.hpp"

namespace bridge_test {

struct SamplerData {
    double sample_period = 0.05;
    double k = 2.0;
    std::array<double, 2> u{};
    std::array<double, 2> y{};
    std::int32_t samples = 0;
    bool valid = false;
    fmu::FixedString<16> label{};  // a String parameter: it cannot cross the link (the bridge refuses a set)
    double start_time = 0.0;       // not a variable: the whole state stays one plain struct
    double next_sample = 0.0;
};

class Sampler : public fmu::Block<Sampler, SamplerData> {
public:
    static void declare(fmu::Table<SamplerData>& t) {
        t.parameter("sample_period", &SamplerData::sample_period, "s", "Time between samples").min(1e-6);
        t.parameter("k", &SamplerData::k, "1", "Gain applied at each sample");
        t.parameter("label", &SamplerData::label, "", "A name for it (a String parameter)");
        t.input("u", &SamplerData::u, "V", "Sampled inputs");
        t.output("y", &SamplerData::y, "V", "k times u at the last sample").depends_on({});
        t.output("samples", &SamplerData::samples, "", "Samples so far").depends_on({});
        t.output("valid", &SamplerData::valid, "", "True once sampled").depends_on({});
    }
    static fmu::ModelInfo describe() {
        fmu::ModelInfo info;
        info.model_identifier = "test_sampler";
        info.model_name = "test_sampler";
        info.description = "Test sample-and-hold gain";
        return info;
    }
    void initialize(double t) override {
        auto& d = data();
        d.y[0] = d.y[1] = 0.0;
        d.samples = 0;
        d.valid = false;
        d.next_sample = t;
        d.start_time = t;
    }
    void evaluate(double) override {}
    std::size_t event_indicator_count() const override { return 0; }
    void event_indicators(double, std::span<double>) override {}
    fmu::EventUpdate event_update(double t, bool time_event_due) override {
        auto& d = data();
        if (time_event_due && fmu::reached(t, d.next_sample)) {
            d.y[0] = d.k * d.u[0];
            d.y[1] = d.k * d.u[1];
            ++d.samples;
            d.valid = true;
            // Counted from the start, so the instants never drift.
            d.next_sample = d.start_time + static_cast<double>(d.samples) * d.sample_period;
        }
        return {};
    }
    double next_time_event() const override { return data().next_sample; }
};

}  // namespace bridge_test

FMU_BLOCK(bridge_test::Sampler)
