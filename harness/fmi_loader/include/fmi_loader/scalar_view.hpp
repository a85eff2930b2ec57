// An FMI 3.0 description seen as scalars: every array variable becomes one variable per element,
// named with its 1-based indices in row-major order ("x[2]", "A[1,3]"), so a master that connects and
// records scalars (and an .ssd naming elements) runs FMI 3.0 arrays unchanged. Each scalar gets its
// own value reference, its position in `elements`; the element says which FMI 3.0 variable and which
// of its values it is.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "fmi_loader/model_description.hpp"

namespace fmi_loader {

struct ScalarElement {
    std::uint32_t value_reference = 0;  // of the FMI 3.0 variable
    std::size_t offset = 0;             // of this element among the variable's values
    std::size_t count = 1;              // values of the whole variable (1: a scalar)
    Fmi3Type type = Fmi3Type::float64;
    std::size_t variable = 0;  // 0-based index of the FMI 3.0 variable in the original description
};

struct ScalarView {
    ModelDescription description;  // model_variables[i].value_reference == i; ModelStructure re-indexed
    std::vector<ScalarElement> elements;
    // The scalars of the original variable `variable` (0-based): [first, first + count).
    std::vector<std::size_t> first_element;
};

// Throws LoaderError (xml_invalid) when an array's start list has neither one value nor one per
// element, and (limit) when the elements exceed limits.max_variables.
ScalarView scalar_view(const ModelDescription& fmi3, const Limits& limits = {});

}  // namespace fmi_loader
