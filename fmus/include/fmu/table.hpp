// The variable table of a block: the one place where a block declares its variables. Each
// declaration binds a name to a field of the block's data struct; arrays become structured names
// (`name[1]` ... `name[N]`), value references are numbered in declaration order, and start values
// are read from a default-constructed data struct, so a default lives only in the struct's member
// initializer.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "fmu/errors.hpp"
#include "fmu/fixed_string.hpp"
#include "fmu/variable.hpp"

namespace fmu {

namespace detail {

template <class T>
struct ScalarTraits;
template <>
struct ScalarTraits<double> {
    static constexpr ValueType type = ValueType::Real;
    static constexpr std::size_t capacity = 0;
};
template <>
struct ScalarTraits<std::int32_t> {
    static constexpr ValueType type = ValueType::Integer;
    static constexpr std::size_t capacity = 0;
};
template <>
struct ScalarTraits<bool> {
    static constexpr ValueType type = ValueType::Boolean;
    static constexpr std::size_t capacity = 0;
};
template <std::size_t N>
struct ScalarTraits<FixedString<N>> {
    static constexpr ValueType type = ValueType::String;
    static constexpr std::size_t capacity = N;
};

// A choice (Table::choice): a C++ enum stored as the FMI Enumeration's 32-bit integer.
template <class T>
requires std::is_enum_v<T>
struct ScalarTraits<T> {
    static_assert(sizeof(T) == sizeof(std::int32_t) && std::is_signed_v<std::underlying_type_t<T>>,
                  "a choice's enum must have a 32-bit signed underlying type (an FMI Enumeration value)");
    static constexpr ValueType type = ValueType::Enumeration;
    static constexpr std::size_t capacity = 0;
};

template <class T>
struct FieldTraits {  // a scalar field
    using Scalar = T;
    static constexpr std::size_t count = 0;
};
template <class T, std::size_t N>
struct FieldTraits<std::array<T, N>> {  // an array field: N structured elements
    using Scalar = T;
    static constexpr std::size_t count = N;
};

}  // namespace detail

// Variables and bookkeeping shared by every table, independent of the data type.
class TableBase {
public:
    const std::vector<Variable>& variables() const { return variables_; }
    // Indices (into variables()) of the continuous states and their derivatives, in state order.
    const std::vector<std::size_t>& states() const { return states_; }
    const std::vector<std::size_t>& derivatives() const { return derivatives_; }
    // Look-ups for tests and tools; throw fmu::Error for an unknown name.
    const Variable& by_name(std::string_view name) const;
    std::size_t index_of(std::string_view name) const;

    // A range of variables just declared, to refine with the chained calls below.
    class Handle {
    public:
        Handle(TableBase& table, std::size_t first, std::size_t last) : table_(table), first_(first), last_(last) {}
        Handle& min(double value);
        Handle& max(double value);
        Handle& range(double lo, double hi) { return min(lo).max(hi); }
        Handle& nominal(double value);
        // Legal but unlikely outside [lo, hi]: taken with a warning giving `why` (a tumble of 5 rad/s).
        Handle& plausible(double lo, double hi, std::string_view why);
        // Only has an effect while the choice or Boolean `variable` is one of `values` (item names, "true",
        // "false"): a setting away from the default otherwise is taken with a warning that it is ignored.
        Handle& applies_when(std::string_view variable, std::initializer_list<std::string_view> values);
        Handle& tunable();   // parameter that may change during the simulation
        Handle& discrete();  // output or local that changes only at events
        // A state whose start the block computes in initialize() (e.g. a filter starting in steady
        // state) rather than taking it from the host: initial="calculated", not settable.
        Handle& calculated_start();
        // Inputs and states that this output or derivative depends on directly. A declared base name
        // ("mag_body") stands for all its elements; an element name ("mag_body[2]") for itself.
        // `elementwise` pairs element i with element i of each named array.
        Handle& depends_on(std::initializer_list<std::string_view> names);
        Handle& depends_elementwise(std::initializer_list<std::string_view> names);
        Handle& derivative_depends_on(std::initializer_list<std::string_view> names);
        // Inputs and parameters this output's value at the end of initialization depends on (an empty
        // list: none, a value the block sets alone whatever its inputs).
        Handle& initial_depends_on(std::initializer_list<std::string_view> names);
        Handle& derivative_depends_elementwise(std::initializer_list<std::string_view> names);

    private:
        void set_dependencies(std::size_t first, std::size_t last, std::initializer_list<std::string_view> names,
                              bool elementwise);
        TableBase& table_;
        std::size_t first_, last_;
    };

protected:
    std::size_t add(Variable v);
    // The items of the Enumeration just declared last; refuses empty, repeated names or values.
    void set_items(std::vector<EnumerationItem> items);
    void mark_state(std::size_t state, std::size_t derivative);
    void check_unit(std::string_view unit) const;

    std::vector<Variable> variables_;
    std::vector<std::size_t> states_, derivatives_;
};

template <class Data>
class Table : public TableBase {
    static_assert(std::is_trivially_copyable_v<Data>, "a block's data must be trivially copyable (FMU state = bytes)");
    static_assert(std::is_standard_layout_v<Data>, "a block's data must be standard layout (fields found by offset)");

public:
    template <class F>
    Handle parameter(std::string_view name, F Data::*field, std::string_view unit, std::string_view description) {
        return declare(name, field, unit, description, Causality::parameter, Variability::fixed, Initial::exact);
    }
    template <class F>
    Handle calculated_parameter(std::string_view name, F Data::*field, std::string_view unit,
                                std::string_view description) {
        return declare(name, field, unit, description, Causality::calculated_parameter, Variability::fixed,
                       Initial::calculated);
    }
    template <class F>
    Handle input(std::string_view name, F Data::*field, std::string_view unit, std::string_view description) {
        return declare(name, field, unit, description, Causality::input, continuous_or_discrete<F>(), Initial::none);
    }
    template <class F>
    Handle output(std::string_view name, F Data::*field, std::string_view unit, std::string_view description) {
        return declare(name, field, unit, description, Causality::output, continuous_or_discrete<F>(),
                       Initial::calculated);
    }
    template <class F>
    Handle local(std::string_view name, F Data::*field, std::string_view unit, std::string_view description) {
        return declare(name, field, unit, description, Causality::local, continuous_or_discrete<F>(),
                       Initial::calculated);
    }
    // A choice among named options: an FMI Enumeration parameter (a drop-down in a tool; settable by
    // item name from the master's --set, an .ssd's ssv:Enumeration, ssv:String or ssv:Integer
    // binding). The field holds the C++ enum, so the block never parses text; the runtime refuses any
    // value that is not an item.
    template <class E>
    Handle choice(std::string_view name, E Data::*field, std::initializer_list<std::pair<std::string_view, E>> items,
                  std::string_view description) {
        static_assert(detail::FieldTraits<E>::count == 0, "a choice is a scalar");
        Handle h = declare(name, field, "", description, Causality::parameter, Variability::fixed, Initial::exact);
        std::vector<EnumerationItem> list;
        for (const auto& [item, value] : items) list.push_back({std::string(item), static_cast<std::int32_t>(value)});
        set_items(std::move(list));
        return h;
    }
    // A continuous state and its derivative (named `der(name[i])`). The state's start value is
    // exact and settable before initialization; the derivative is calculated.
    template <class F>
    Handle state(std::string_view name, F Data::*field, F Data::*derivative, std::string_view unit,
                 std::string_view description) {
        static_assert(std::is_same_v<typename detail::FieldTraits<F>::Scalar, double>, "states are Real");
        Handle states =
            declare(name, field, unit, description, Causality::local, Variability::continuous, Initial::exact);
        const std::size_t first_state = variables_.size() - count_of<F>();
        const std::string der_name = "der(" + std::string(name) + ")";
        declare(der_name, derivative, derivative_unit(unit), "Time derivative of " + std::string(name),
                Causality::local, Variability::continuous, Initial::calculated);
        const std::size_t first_der = variables_.size() - count_of<F>();
        for (std::size_t i = 0; i < count_of<F>(); ++i) {
            variables_[first_der + i].name = "der(" + variables_[first_state + i].name + ")";
            mark_state(first_state + i, first_der + i);
        }
        return states;
    }

    // Where a field lives inside Data; member pointers give no offset directly, so measure it on an
    // object (valid for standard-layout types, which the static_assert above guarantees).
    template <class F>
    static std::size_t offset_of(F Data::*field) {
        static const Data probe{};
        return static_cast<std::size_t>(reinterpret_cast<const char*>(&(probe.*field)) -
                                        reinterpret_cast<const char*>(&probe));
    }

private:
    template <class F>
    static constexpr std::size_t count_of() {
        const std::size_t n = detail::FieldTraits<F>::count;
        return n == 0 ? 1 : n;
    }
    template <class F>
    static constexpr Variability continuous_or_discrete() {
        return detail::ScalarTraits<typename detail::FieldTraits<F>::Scalar>::type == ValueType::Real
                   ? Variability::continuous
                   : Variability::discrete;
    }
    static std::string derivative_unit(std::string_view unit) {
        if (unit.empty()) return "1/s";
        return std::string(unit) + "/s";
    }

    template <class F>
    Handle declare(std::string_view name, F Data::*field, std::string_view unit, std::string_view description,
                   Causality causality, Variability variability, Initial initial) {
        using Traits = detail::FieldTraits<F>;
        using Scalar = typename Traits::Scalar;
        using ScalarT = detail::ScalarTraits<Scalar>;
        check_unit(unit);
        const std::size_t base = offset_of(field);
        const std::size_t first = variables_.size();
        for (std::size_t i = 0; i < count_of<F>(); ++i) {
            Variable v;
            v.base_name = std::string(name);
            v.name = Traits::count == 0 ? std::string(name) : std::string(name) + "[" + std::to_string(i + 1) + "]";
            v.description = std::string(description);
            v.unit = std::string(unit);
            v.type = ScalarT::type;
            v.causality = causality;
            v.variability = variability;
            v.initial = initial;
            v.offset = base + i * sizeof(Scalar);
            v.string_capacity = ScalarT::capacity;
            add(std::move(v));
        }
        return Handle(*this, first, variables_.size());
    }
};

}  // namespace fmu
