// How a block's variable table reads in FMI 3.0: each declared name is one variable, an array
// (<Dimension>) where the table declared an array, so a field or a quaternion is one variable instead
// of the FMI 2.0 description's elements `name[1]` ... `name[N]`. A variable's FMI 3.0 value reference
// is its first element's FMI 2.0 one, so both descriptions come from the one table with the same
// numbers. FMI 3.0 also wants the independent variable (`time`) declared, and the event indicators
// as variables (`event_indicators`, where the block has any): both get value references after the
// table's. Plain C++, no FMI types.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "fmu/table.hpp"

namespace fmu {

struct Fmi3Variable {
    std::size_t first = 0;  // index into the table's variables() of its first element
    std::size_t count = 1;  // number of elements
    bool array = false;     // declared as an array (even of one element)
    std::uint32_t value_reference = 0;
};

class Fmi3View {
public:
    // Throws fmu::Error when the elements of an array differ in what FMI 3.0 states once per
    // variable (unit, description, causality, variability, initial, min, max, nominal).
    Fmi3View(const TableBase& table, std::size_t event_indicator_count);

    const std::vector<Fmi3Variable>& variables() const { return variables_; }
    // The variable a value reference names, or null (also for time and the event indicators).
    const Fmi3Variable* find(std::uint32_t value_reference) const;
    // The variable the table's element `index` belongs to.
    const Fmi3Variable& owner(std::size_t index) const { return variables_[owner_[index]]; }
    // The table's FMI 2.0 value references of a variable's elements, in order.
    std::span<const std::uint32_t> element_references(const Fmi3Variable& v) const {
        return std::span<const std::uint32_t>(element_references_).subspan(v.first, v.count);
    }
    std::uint32_t time_reference() const { return time_reference_; }
    std::uint32_t event_indicators_reference() const { return time_reference_ + 1; }
    std::size_t event_indicator_count() const { return event_indicator_count_; }

private:
    std::vector<Fmi3Variable> variables_;
    std::vector<std::size_t> owner_;                 // per table element: index into variables_
    std::vector<std::uint32_t> element_references_;  // per table element
    std::vector<std::size_t> by_reference_;          // value reference -> index into variables_ + 1, 0: none
    std::uint32_t time_reference_ = 0;
    std::size_t event_indicator_count_ = 0;
};

}  // namespace fmu
