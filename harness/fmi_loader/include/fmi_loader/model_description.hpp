// The content of an FMI 2.0 modelDescription.xml (FMI 2.0.4 standard, section 2.2) or an FMI 3.0 one
// (FMI 3.0.2, section 2.4), with the standard's defaults already applied so users never re-derive them.
// An FMI 3.0 description fills the same model: its types keep their own name in `fmi3_type` beside the
// FMI 2.0 base kind in `type`, arrays carry their `dimensions`, and the ModelStructure's value
// references are turned into the 1-based indices FMI 2.0 uses.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fmi_loader/limits.hpp"

namespace fmi_loader {

enum class Causality { parameter, calculated_parameter, input, output, local, independent, structural_parameter };
enum class Variability { constant, fixed, tunable, discrete, continuous };
enum class Initial { none, exact, approx, calculated };  // none: the attribute is not allowed (input, independent)
enum class VariableType { real, integer, boolean, string, enumeration };
// FMI 3.0's variable types (section 2.4.7.4). Their FMI 2.0 base kind (`ScalarVariable::type`):
// Float32/64 real; the eight integers integer; Boolean boolean; String string; Binary string (its
// value travels as hexadecimal text); Enumeration enumeration; Clock boolean (ticking or not).
enum class Fmi3Type {
    float32,
    float64,
    int8,
    uint8,
    int16,
    uint16,
    int32,
    uint32,
    int64,
    uint64,
    boolean,
    string,
    binary,
    enumeration,
    clock
};
VariableType base_kind(Fmi3Type t) noexcept;

std::string_view to_string(Causality c) noexcept;
std::string_view to_string(Variability v) noexcept;
std::string_view to_string(Initial i) noexcept;
std::string_view to_string(VariableType t) noexcept;
std::string_view to_string(Fmi3Type t) noexcept;  // the element name: "Float64", "UInt8", ...

// FMI 2.0.4 section 2.2.7, table of causality x variability: is the combination allowed at all?
bool is_valid_combination(Causality c, Variability v) noexcept;
// The default of `initial` for a valid combination (same table, cases A-E).
Initial default_initial(Causality c, Variability v) noexcept;
// Whether an explicitly given `initial` is allowed for the combination.
bool is_allowed_initial(Causality c, Variability v, Initial i) noexcept;

struct BaseUnit {
    int kg = 0, m = 0, s = 0, A = 0, K = 0, mol = 0, cd = 0, rad = 0;
    double factor = 1.0, offset = 0.0;
};

struct DisplayUnit {
    std::string name;
    double factor = 1.0, offset = 0.0;
};

struct Unit {
    std::string name;
    std::optional<BaseUnit> base_unit;
    std::vector<DisplayUnit> display_units;
};

struct EnumerationItem {
    std::string name;
    std::int64_t value = 0;
    std::string description;
};

struct SimpleType {
    std::string name, description;
    VariableType type = VariableType::real;
    std::optional<Fmi3Type> fmi3_type;  // FMI 3.0 only
    std::string quantity, unit, display_unit;
    std::optional<double> min, max, nominal;
    std::vector<EnumerationItem> items;  // Enumeration only
};

struct LogCategory {
    std::string name, description;
};

struct DefaultExperiment {
    std::optional<double> start_time, stop_time, tolerance, step_size;
};

// One <Dimension> of an FMI 3.0 array variable: a fixed size or the value reference of the
// structural parameter (or constant) holding it.
struct Dimension {
    std::optional<std::uint64_t> start;
    std::optional<std::uint32_t> value_reference;
};

struct ScalarVariable {
    std::string name;
    std::uint32_t value_reference = 0;
    std::string description;
    Causality causality = Causality::local;  // default per section 2.2.7
    Variability variability = Variability::continuous;
    Initial initial = Initial::none;  // explicit value or the table's default
    bool initial_given = false;       // whether the XML stated `initial`
    bool can_handle_multiple_set_per_time_instant = true;
    VariableType type = VariableType::real;
    std::string declared_type;
    std::optional<std::string> start;  // raw attribute text; typed via start_as_*
    // Own attributes, completed from the declaredType's SimpleType when the variable omits them.
    std::string quantity, unit, display_unit;
    std::optional<double> min, max, nominal;
    std::optional<std::size_t> derivative;  // 1-based index of the state this is the derivative of
    bool reinit = false;
    bool relative_quantity = false;
    // FMI 3.0 only.
    std::optional<Fmi3Type> fmi3_type;
    std::vector<Dimension> dimensions;      // empty: a scalar
    std::vector<std::string> start_values;  // String and Binary: the <Start value> children, in order
    bool intermediate_update = false;
    std::optional<std::uint32_t> previous;  // value reference of the variable this is the previous of
    std::vector<std::uint32_t> clocks;      // value references of the clocks this variable is clocked by
    std::string mime_type;                  // Binary
    std::optional<std::uint64_t> max_size;  // Binary

    std::optional<double> start_as_real() const;   // Real, Integer, Enumeration
    std::optional<bool> start_as_boolean() const;  // "true"/"false"/"1"/"0"
};

// The start of a UInt64 structural parameter or constant as an array size: a whole number from 0 to
// 2^64 - 1 (blanks around it allowed); none for anything else ("1e30", "abc", "-5", no start).
std::optional<std::uint64_t> dimension_start(const ScalarVariable& p) noexcept;

struct Unknown {
    std::size_t index = 0;                                 // 1-based into model_variables
    std::optional<std::vector<std::size_t>> dependencies;  // absent: depends on all knowns
    std::vector<std::string> dependencies_kind;
};

struct ModelStructure {
    std::vector<Unknown> outputs, derivatives, initial_unknowns;
    std::vector<Unknown> event_indicators, clocked_states;  // FMI 3.0 only
};

struct ModelExchangeInfo {
    std::string model_identifier;
    bool needs_execution_tool = false;
    bool completed_integrator_step_not_needed = false;
    bool can_be_instantiated_only_once_per_process = false;
    bool can_not_use_memory_management_functions = false;
    bool can_get_and_set_fmu_state = false;
    bool can_serialize_fmu_state = false;
    bool provides_directional_derivative = false;
    // FMI 3.0 only (completed_integrator_step_not_needed is !needsCompletedIntegratorStep there).
    bool provides_evaluate_discrete_states = false;
};

struct CoSimulationInfo {
    std::string model_identifier;
    bool needs_execution_tool = false;
    bool can_handle_variable_communication_step_size = false;
    bool can_interpolate_inputs = false;
    int max_output_derivative_order = 0;
    bool can_run_asynchronuously = false;  // the standard's spelling
    bool can_be_instantiated_only_once_per_process = false;
    bool can_not_use_memory_management_functions = false;
    bool can_get_and_set_fmu_state = false;
    bool can_serialize_fmu_state = false;
    bool provides_directional_derivative = false;
    // FMI 3.0 only (section 4.4.1).
    bool has_event_mode = false;
    bool provides_intermediate_update = false;
    bool might_return_early_from_do_step = false;
    bool can_return_early_after_intermediate_update = false;
    bool provides_evaluate_discrete_states = false;
    std::optional<double> fixed_internal_step_size;
    int recommended_intermediate_input_smoothness = 0;
};

// FMI 3.0 Scheduled Execution (section 5): read so that an importer can name it when refusing it.
struct ScheduledExecutionInfo {
    std::string model_identifier;
};

struct ModelDescription {
    std::string fmi_version, model_name, guid, description, author, version, generation_tool;
    std::string variable_naming_convention = "flat";
    std::size_t number_of_event_indicators = 0;
    std::optional<ModelExchangeInfo> model_exchange;
    std::optional<CoSimulationInfo> co_simulation;
    std::optional<ScheduledExecutionInfo> scheduled_execution;  // FMI 3.0 only
    std::vector<Unit> unit_definitions;
    std::vector<SimpleType> type_definitions;
    std::vector<LogCategory> log_categories;
    std::optional<DefaultExperiment> default_experiment;
    std::vector<ScalarVariable> model_variables;
    ModelStructure model_structure;

    bool is_fmi3() const noexcept { return fmi_version.rfind("3.", 0) == 0; }
    // Number of continuous states = the scalars of the ModelStructure's derivatives (FMI 2.0.4 section
    // 2.2.8: one per Unknown; FMI 3.0: an array derivative counts its elements).
    std::size_t number_of_continuous_states() const noexcept;
    // Elements of a variable: 1 for a scalar, else the product of its dimensions, a dimension given by
    // a structural parameter taking that parameter's start value.
    std::size_t element_count(const ScalarVariable& v) const noexcept;
    // The sizes of `v`'s dimensions, resolved as element_count does.
    std::vector<std::size_t> extents(const ScalarVariable& v) const;
    const ScalarVariable* find_by_reference(std::uint32_t value_reference) const noexcept;  // FMI 3.0
    const ScalarVariable* find_variable(std::string_view name) const noexcept;
    const Unit* find_unit(std::string_view name) const noexcept;
    const SimpleType* find_type(std::string_view name) const noexcept;
};

// Parses an FMI 2.0 or 3.0 description (the fmiVersion attribute decides) with libxml2 without network access, without loading a DTD and without expanding
// entities; a document carrying a DOCTYPE is refused (an FMU never needs one). Throws LoaderError
// (xml_parse, xml_invalid) naming `source_name`.
// Within `limits` (file size, variables, event indicators: LoaderErrc::limit). Also refused: a
// modelIdentifier that is not a C identifier, duplicate variable names, two start values in one
// alias set (same valueReference and base type), and indices beyond ModelVariables.
ModelDescription parse_model_description(std::string_view xml, const std::string& source_name = "<memory>",
                                         const Limits& limits = {});
ModelDescription read_model_description(const std::filesystem::path& file, const Limits& limits = {});

}  // namespace fmi_loader
