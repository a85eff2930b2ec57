// The notes the runtime would log for a block's values (fmu::setting_notes against the block's own variable
// table and its defaults as constructed), for the blocks' setting-notes tests.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "fmu/table.hpp"
#include "fmu/value_check.hpp"

namespace fmu::testing {

template <class BlockT>
std::vector<std::string> setting_notes_of(const typename BlockT::Data& values) {
    using Data = typename BlockT::Data;
    Table<Data> table;
    BlockT::declare(table);
    const Data defaults;
    return setting_notes(table.variables(), std::as_bytes(std::span(&values, 1)),
                         std::as_bytes(std::span(&defaults, 1)));
}

}  // namespace fmu::testing
