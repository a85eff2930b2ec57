// fmi2DeSerializeFMUstate of one block (linked in as fmu::make_model). A checksum guards the payload,
// so random bytes would never get past it: the input is a list of edits to a valid serialized state
// (2 bytes offset, 1 byte length, that many bytes), applied to the block's bytes and sealed with a
// fresh checksum, as a deliberate forger would. A state the FMU accepts is then used: set, one step,
// every variable read. Any crash, sanitizer report or hang is a finding. First byte odd: the input
// itself is passed as the serialized state instead (the header's checks).
#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "fmi2/fmi2Functions.h"
#include "fmu/description.hpp"
#include "fmu/model.hpp"
#include "fmu/state_check.hpp"
#include "fmu/table.hpp"

namespace {

void quiet(fmi2ComponentEnvironment, fmi2String, fmi2Status, fmi2String, fmi2String, ...) {}
fmi2CallbackFunctions callbacks{quiet, nullptr, nullptr, nullptr, nullptr};

constexpr std::size_t header = 8 + 8 + 8 + 8 + 1 + 40;  // fmus/src/instance.cpp, layout version 2

struct Block {
    std::unique_ptr<fmu::Model> model = fmu::make_model();
    std::string guid = fmu::description_guid(*model);
    std::vector<fmi2Byte> valid;  // a serialized state just after initialization
    std::vector<fmi2ValueReference> reals, integers, booleans, strings;

    fmi2Component start() const {
        fmi2Component c =
            fmi2Instantiate("fuzz", fmi2CoSimulation, guid.c_str(), nullptr, &callbacks, fmi2False, fmi2False);
        if (!c || fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0) != fmi2OK ||
            fmi2EnterInitializationMode(c) != fmi2OK || fmi2ExitInitializationMode(c) != fmi2OK)
            std::abort();
        return c;
    }

    Block() {
        for (const auto& v : model->table().variables()) {
            switch (v.type) {
                case fmu::ValueType::Real:
                    reals.push_back(v.value_reference);
                    break;
                case fmu::ValueType::Integer:
                case fmu::ValueType::Enumeration:
                    integers.push_back(v.value_reference);
                    break;
                case fmu::ValueType::Boolean:
                    booleans.push_back(v.value_reference);
                    break;
                case fmu::ValueType::String:
                    strings.push_back(v.value_reference);
                    break;
            }
        }
        fmi2Component c = start();
        fmi2FMUstate s = nullptr;
        size_t size = 0;
        if (fmi2GetFMUstate(c, &s) != fmi2OK || fmi2SerializedFMUstateSize(c, s, &size) != fmi2OK) std::abort();
        valid.resize(size);
        if (fmi2SerializeFMUstate(c, s, valid.data(), size) != fmi2OK) std::abort();
        fmi2FreeFMUstate(c, &s);
        fmi2FreeInstance(c);
    }
};

const Block& block() {
    static const Block b;
    return b;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const Block& b = block();
    std::vector<fmi2Byte> bytes;
    if (size > 0 && (data[0] & 1)) {
        bytes.assign(reinterpret_cast<const char*>(data) + 1, reinterpret_cast<const char*>(data) + size);
    } else {
        bytes = b.valid;
        const std::size_t payload = b.valid.size() - header - 8;
        for (std::size_t i = size > 0 ? 1 : 0; i + 3 <= size;) {
            const std::size_t offset =
                (static_cast<std::size_t>(data[i]) | static_cast<std::size_t>(data[i + 1]) << 8) % payload;
            const std::size_t length = data[i + 2] % 17;
            i += 3;
            for (std::size_t k = 0; k < length && i < size && offset + k < payload; ++k, ++i)
                bytes[header + offset + k] = static_cast<fmi2Byte>(data[i]);
        }
        const std::uint64_t sum = fmu::serialized_state_checksum(std::span<const char>(bytes.data(), bytes.size() - 8));
        std::memcpy(bytes.data() + bytes.size() - 8, &sum, 8);
    }

    fmi2Component c = b.start();
    fmi2FMUstate state = nullptr;
    if (fmi2DeSerializeFMUstate(c, bytes.data(), bytes.size(), &state) == fmi2OK) {
        if (fmi2SetFMUstate(c, state) == fmi2OK && fmi2DoStep(c, 0.0, 1e-3, fmi2True) == fmi2OK) {
            std::vector<fmi2Real> r(b.reals.size());
            std::vector<fmi2Integer> n(b.integers.size());
            std::vector<fmi2Boolean> flags(b.booleans.size());
            std::vector<fmi2String> s(b.strings.size());
            fmi2GetReal(c, b.reals.data(), b.reals.size(), r.data());
            fmi2GetInteger(c, b.integers.data(), b.integers.size(), n.data());
            fmi2GetBoolean(c, b.booleans.data(), b.booleans.size(), flags.data());
            fmi2GetString(c, b.strings.data(), b.strings.size(), s.data());
        }
        fmi2FreeFMUstate(c, &state);
    }
    fmi2FreeInstance(c);
    return 0;
}
