// One row of a block's variable table: everything the model description, the FMI getters and
// setters and the table-driven tests need to know about a scalar variable. Plain C++, no FMI types.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fmu {

// Enumeration: an FMI 2.0 Enumeration (a <SimpleType> with <Item>s), accessed as an Integer; the
// block's field is a C++ enum with a 32-bit underlying type (Table::choice).
enum class ValueType { Real, Integer, Boolean, String, Enumeration };
enum class Causality { parameter, calculated_parameter, input, output, local, independent };
enum class Variability { constant, fixed, tunable, discrete, continuous };
enum class Initial { none, exact, approx, calculated };

std::string_view to_string(ValueType v);
std::string_view to_string(Causality c);  // the standard's spelling, e.g. "calculatedParameter"
std::string_view to_string(Variability v);
std::string_view to_string(Initial i);

// One item of an Enumeration: the name a user types or picks, and the integer the FMU stores.
struct EnumerationItem {
    std::string name;
    std::int32_t value = 0;
};

struct Variable {
    std::string name;       // structured name: "mag_body[2]", "der(b_filt[1])"
    std::string base_name;  // the declared name: "mag_body"
    std::string description;
    std::string unit;  // empty: dimensionless without a unit
    ValueType type = ValueType::Real;
    Causality causality = Causality::local;
    Variability variability = Variability::continuous;
    Initial initial = Initial::none;
    std::uint32_t value_reference = 0;
    std::optional<double> min, max, nominal;
    // Enumeration only: its items, and the name of its type definition (the variable's name in
    // CamelCase: "sun_method" has type "SunMethod").
    std::vector<EnumerationItem> items;
    std::string declared_type;
    std::size_t offset = 0;                    // byte offset of the value in the block's data struct
    std::size_t string_capacity = 0;           // String only
    std::optional<std::size_t> derivative_of;  // index of the state this is the derivative of
    // Outputs and derivatives: indices of the inputs and states this value depends on directly
    // (empty optional: not declared, meaning "may depend on every known").
    std::optional<std::vector<std::size_t>> dependencies;
    // Outputs with initial="calculated": indices of the inputs and parameters its value at the end of
    // initialization depends on (empty optional: not declared, "may depend on every known"). FMI 2.0
    // §2.2.8 InitialUnknowns; a host that breaks algebraic loops in initialization reads it.
    std::optional<std::vector<std::size_t>> initial_dependencies;
    // Parameters: a legal value outside [plausible_min, plausible_max] is taken, with a warning that says why
    // it is unlikely (plausible_note); the hard limits are min and max.
    std::optional<double> plausible_min, plausible_max;
    std::string plausible_note;
    // Parameters: the variable has an effect only while the choice or Boolean `applies_when_variable` holds
    // one of applies_when_values (item names, "true" or "false"); set away from its default otherwise, a
    // warning says it is ignored. Empty: it always applies.
    std::string applies_when_variable;
    std::vector<std::string> applies_when_values;

    bool has_start() const {
        return causality == Causality::input || initial == Initial::exact || initial == Initial::approx ||
               (variability == Variability::constant);
    }
    bool is_state() const { return is_state_; }
    bool is_derivative() const { return derivative_of.has_value(); }
    // Enumeration: the item with this name or value, or null.
    const EnumerationItem* item_named(std::string_view item) const;
    const EnumerationItem* item_valued(std::int32_t value) const;
    // Enumeration: "a, b, c", for messages and documentation.
    std::string item_names() const;

    bool is_state_ = false;  // set by the table when a derivative refers to this variable
};

}  // namespace fmu
