// An example block on the installed runtime: a battery pack's temperature with a thermostat-controlled
// heater, as a small satellite carries to keep its cells above their charging limit in eclipse.
//
//   C dT/dt = G (T_body - T) + P_heater,   the heater on below t_on and off above t_off (t_on < t_off)
//
// One continuous state, two state events (the thermostat's thresholds), a Boolean output and a choice.
#include <cstdint>

#include "fmu/block.hpp"

namespace battery_heater {

enum class Thermostat : std::int32_t { automatic = 1, always_off = 2 };

struct Data {
    double heat_capacity = 450.0;   // J/K: 0.5 kg of cells at ~900 J/(kg K)
    double conductance = 0.05;      // W/K to the spacecraft body
    double heater_power = 2.0;      // W
    double t_on = 273.15 + 5.0;     // K: below it the heater switches on
    double t_off = 273.15 + 10.0;   // K: above it the heater switches off
    double t_start = 273.15 + 8.0;  // K
    Thermostat thermostat = Thermostat::automatic;
    double t_body = 273.15 - 20.0;  // input: the body the pack is mounted on, K
    double temperature = 273.15 + 8.0, der_temperature = 0.0;
    bool heater_on = false;
    double power = 0.0;      // output: the heater's power now, W
    double heat_flow = 0.0;  // output: heat flowing from the body into the pack, W
};

class BatteryHeater : public fmu::Block<BatteryHeater, Data> {
public:
    static void declare(fmu::Table<Data>& t) {
        t.parameter("heat_capacity", &Data::heat_capacity, "J/K", "Heat capacity of the pack").min(1e-3);
        t.parameter("conductance", &Data::conductance, "W/K", "Conductance from the pack to the body").min(0.0);
        t.parameter("heater_power", &Data::heater_power, "W", "Heater power when on").min(0.0);
        t.parameter("t_on", &Data::t_on, "K", "The heater switches on below this temperature").min(0.0);
        t.parameter("t_off", &Data::t_off, "K", "The heater switches off above this temperature").min(0.0);
        t.parameter("t_start", &Data::t_start, "K", "Pack temperature at the start").min(0.0);
        t.choice("thermostat", &Data::thermostat,
                 {{"automatic", Thermostat::automatic}, {"always_off", Thermostat::always_off}},
                 "Thermostat mode: automatic, or the heater kept off");
        t.input("t_body", &Data::t_body, "K", "Temperature of the body the pack is mounted on").min(0.0);
        t.state("temperature", &Data::temperature, &Data::der_temperature, "K", "Pack temperature")
            .calculated_start()
            .nominal(300.0);
        t.output("heater_on", &Data::heater_on, "", "Heater switched on").depends_on({});
        t.output("power", &Data::power, "W", "Heater power now").depends_on({});
        t.output("heat_flow", &Data::heat_flow, "W", "Heat flowing from the body into the pack")
            .depends_on({"t_body", "temperature"});
    }
    static fmu::ModelInfo describe() {
        fmu::ModelInfo info;
        info.model_identifier = "battery_heater";
        info.model_name = "battery_heater";
        info.description = "Battery pack temperature with a thermostat-controlled heater (example block)";
        info.documentation_html = "<p>An example of a block built outside the toolkit on its installed package.</p>";
        info.default_experiment.stop_time = 20000.0;
        info.default_experiment.step_size = 10.0;
        return info;
    }
    void validate() const override {
        if (!(data().t_on < data().t_off)) throw fmu::Error("t_on must be below t_off (the thermostat's hysteresis)");
    }
    void initialize(double) override {
        auto& d = data();
        d.temperature = d.t_start;
        d.heater_on = d.thermostat == Thermostat::automatic && d.temperature < d.t_on;
    }
    void evaluate(double) override {
        auto& d = data();
        d.power = d.heater_on ? d.heater_power : 0.0;
        d.heat_flow = d.conductance * (d.t_body - d.temperature);
        d.der_temperature = (d.heat_flow + d.power) / d.heat_capacity;
    }
    std::size_t event_indicator_count() const override { return 1; }
    // The threshold the thermostat waits for: t_off while heating, t_on while not.
    void event_indicators(double, std::span<double> z) override {
        const auto& d = data();
        z[0] = d.heater_on ? d.t_off - d.temperature : d.temperature - d.t_on;
    }
    // A located crossing may stop a hair short of its threshold: the margin (far above the crossing's
    // location tolerance, far below any thermostat's accuracy) keeps the switch from waiting for it.
    fmu::EventUpdate event_update(double, bool) override {
        constexpr double margin = 1e-6;  // K
        auto& d = data();
        d.heater_on = d.thermostat == Thermostat::automatic &&
                      (d.heater_on ? d.temperature < d.t_off - margin : d.temperature <= d.t_on + margin);
        return {};
    }
};

}  // namespace battery_heater

FMU_BLOCK(battery_heater::BatteryHeater)
