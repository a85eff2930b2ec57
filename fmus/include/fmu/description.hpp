// Facts about a block's model description that both the FMU binary and the build-time writer need,
// computed the same way in both: the start-value text of a variable and the GUID, a hash of the
// description's content (so any change to the interface changes the GUID, and an importer holding an
// old modelDescription.xml is refused by fmi2Instantiate).
#pragma once

#include <span>
#include <string>

#include "fmu/model.hpp"

namespace fmu {

// The start value of `v` as the model description spells it, read from the bytes of a
// default-constructed data struct. Reals round-trip (17 significant digits).
std::string start_text(const Variable& v, std::span<const std::byte> defaults);

// Canonical text of everything the model description states, in a fixed order.
std::string description_fingerprint(const Model& model);

// "{xxxxxxxx-xxxx-xxxx-xxxx-xxxxxxxxxxxx}" from a 128-bit FNV-1a hash of the fingerprint.
std::string description_guid(const Model& model);

// A Real as the model description and the fingerprint spell it (round-trip precision).
std::string format_real(double value);

}  // namespace fmu
