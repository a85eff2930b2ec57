// One FMI 3.0 archive opened for the suite: unpacked (the loader's archive), its description read
// with libxml2 into what the tests need, its binary loaded with dlopen and every fmi3 function the
// tests call resolved. Independent of the runtime under test: the tests see only the archive.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fmi3/fmi3FunctionTypes.h"
#include "fmi_loader/fmu_archive.hpp"

namespace conformance3 {

struct Variable3 {
    std::string name, type;  // type: the element name, "Float64", "Int32", "Enumeration", ...
    std::uint32_t value_reference = 0;
    std::string causality = "local", variability = "continuous", initial;
    std::vector<std::string> start;  // one entry per element where the description gives a start
    std::size_t count = 1;           // product of the <Dimension> starts
    bool array = false;
    std::optional<std::uint32_t> derivative;  // value reference of the state
};

struct Description3 {
    std::string model_identifier, token;
    double start_time = 0.0, stop_time = 1.0, step_size = 0.01;
    std::vector<Variable3> variables;
    std::vector<std::uint32_t> outputs, derivatives, event_indicators;
    bool has_event_mode = false, might_return_early = false;
    const Variable3& by_reference(std::uint32_t vr) const;
    std::size_t count_of(const std::vector<std::uint32_t>& refs) const;  // elements of those variables
};

Description3 read_description3(const std::filesystem::path& xml);

struct Functions3 {
    fmi3InstantiateModelExchangeTYPE* instantiate_me = nullptr;
    fmi3InstantiateCoSimulationTYPE* instantiate_cs = nullptr;
    fmi3InstantiateScheduledExecutionTYPE* instantiate_se = nullptr;
    fmi3FreeInstanceTYPE* free_instance = nullptr;
    fmi3EnterInitializationModeTYPE* enter_initialization_mode = nullptr;
    fmi3ExitInitializationModeTYPE* exit_initialization_mode = nullptr;
    fmi3EnterEventModeTYPE* enter_event_mode = nullptr;
    fmi3TerminateTYPE* terminate = nullptr;
    fmi3ResetTYPE* reset = nullptr;
    fmi3GetFloat64TYPE* get_float64 = nullptr;
    fmi3GetFloat32TYPE* get_float32 = nullptr;
    fmi3GetInt32TYPE* get_int32 = nullptr;
    fmi3GetInt64TYPE* get_int64 = nullptr;
    fmi3GetBooleanTYPE* get_boolean = nullptr;
    fmi3GetStringTYPE* get_string = nullptr;
    fmi3SetFloat64TYPE* set_float64 = nullptr;
    fmi3SetInt32TYPE* set_int32 = nullptr;
    fmi3SetInt64TYPE* set_int64 = nullptr;
    fmi3SetBooleanTYPE* set_boolean = nullptr;
    fmi3SetStringTYPE* set_string = nullptr;
    fmi3GetFMUStateTYPE* get_fmu_state = nullptr;
    fmi3SetFMUStateTYPE* set_fmu_state = nullptr;
    fmi3FreeFMUStateTYPE* free_fmu_state = nullptr;
    fmi3SerializedFMUStateSizeTYPE* serialized_size = nullptr;
    fmi3SerializeFMUStateTYPE* serialize = nullptr;
    fmi3DeserializeFMUStateTYPE* deserialize = nullptr;
    fmi3EnterConfigurationModeTYPE* enter_configuration_mode = nullptr;
    fmi3UpdateDiscreteStatesTYPE* update_discrete_states = nullptr;
    fmi3EnterContinuousTimeModeTYPE* enter_continuous_time_mode = nullptr;
    fmi3CompletedIntegratorStepTYPE* completed_integrator_step = nullptr;
    fmi3SetTimeTYPE* set_time = nullptr;
    fmi3SetContinuousStatesTYPE* set_continuous_states = nullptr;
    fmi3GetContinuousStateDerivativesTYPE* get_derivatives = nullptr;
    fmi3GetEventIndicatorsTYPE* get_event_indicators = nullptr;
    fmi3GetContinuousStatesTYPE* get_continuous_states = nullptr;
    fmi3GetNumberOfContinuousStatesTYPE* get_number_of_states = nullptr;
    fmi3GetNumberOfEventIndicatorsTYPE* get_number_of_event_indicators = nullptr;
    fmi3EnterStepModeTYPE* enter_step_mode = nullptr;
    fmi3DoStepTYPE* do_step = nullptr;
};

class Fmu3 {
public:
    explicit Fmu3(const std::filesystem::path& fmu);
    ~Fmu3();
    Fmu3(const Fmu3&) = delete;
    Fmu3& operator=(const Fmu3&) = delete;
    const Description3& md() const { return md_; }
    const Functions3& f() const { return f_; }
    const fmi_loader::FmuArchive& archive() const { return archive_; }

private:
    fmi_loader::FmuArchive archive_;
    Description3 md_;
    void* handle_ = nullptr;
    Functions3 f_;
};

// The log of one instance (its instanceEnvironment).
struct Log3 {
    std::vector<std::pair<fmi3Status, std::string>> records;
    bool has_error() const;
    std::string dump() const;
};

class Instance3 {
public:
    enum class Kind { model_exchange, co_simulation };
    Instance3(Fmu3& fmu, Kind kind, bool event_mode_used = false, bool early_return_allowed = false,
              const std::string& token = "", fmi3IntermediateUpdateCallback intermediate_update = nullptr);
    ~Instance3();
    Instance3(const Instance3&) = delete;
    Instance3& operator=(const Instance3&) = delete;
    fmi3Instance c() const { return c_; }
    const Functions3& f() const { return fmu_.f(); }
    const Description3& md() const { return fmu_.md(); }
    Log3& log() { return *log_; }
    // Enter and exit initialization at the default start time, stop time given.
    fmi3Status initialize();
    // All elements of a Float64 variable.
    std::vector<double> get_float64(const Variable3& v);
    // Every Float64 output, element by element.
    std::vector<double> outputs();

private:
    Fmu3& fmu_;
    std::unique_ptr<Log3> log_;
    fmi3Instance c_ = nullptr;
};

// The FMI 3.0 archives of the build ($PVATT_FMU3_DIR overrides) and each one's FMI 2.0 archive.
std::vector<std::filesystem::path> fmu3_files();
std::filesystem::path fmi2_archive_of(const std::filesystem::path& fmu3);

}  // namespace conformance3
