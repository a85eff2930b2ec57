#include "fmu/state_check.hpp"

#include <algorithm>
#include <cstring>

#include "fmu/model.hpp"
#include "fmu/table.hpp"

namespace fmu {

namespace {

[[noreturn]] void refuse(const Variable& v, const std::string& what) {
    throw Error("restored FMU state: " + v.name + " " + what);
}

void check_variable(const Variable& v, std::span<const std::byte> bytes) {
    const std::byte* at = bytes.data() + v.offset;
    switch (v.type) {
        case ValueType::Real: {
            double x = 0.0;
            std::memcpy(&x, at, sizeof x);
            if (std::isnan(x)) refuse(v, "is NaN");
            if (std::isinf(x) && (v.min || v.max)) refuse(v, "is infinite");
            if (v.min && x < *v.min)
                refuse(v, "= " + std::to_string(x) + " is below its min " + std::to_string(*v.min));
            if (v.max && x > *v.max)
                refuse(v, "= " + std::to_string(x) + " is above its max " + std::to_string(*v.max));
            break;
        }
        case ValueType::Integer: {
            std::int32_t x = 0;
            std::memcpy(&x, at, sizeof x);
            if (v.min && x < *v.min) refuse(v, "= " + std::to_string(x) + " is below its min");
            if (v.max && x > *v.max) refuse(v, "= " + std::to_string(x) + " is above its max");
            break;
        }
        case ValueType::Boolean: {
            unsigned char byte = 0;
            std::memcpy(&byte, at, 1);
            if (byte > 1) refuse(v, "is not a boolean (byte " + std::to_string(byte) + ")");
            break;
        }
        case ValueType::String: {
            const char* text = reinterpret_cast<const char*>(at);
            const std::size_t length = strnlen(text, v.string_capacity + 1);
            if (length > v.string_capacity)
                refuse(v, "is not terminated within its " + std::to_string(v.string_capacity) + " characters");
            break;
        }
        case ValueType::Enumeration: {
            std::int32_t x = 0;
            std::memcpy(&x, at, sizeof x);
            if (!v.item_valued(x)) refuse(v, "= " + std::to_string(x) + " is not an item of " + v.declared_type);
            break;
        }
    }
}

}  // namespace

std::uint64_t serialized_state_checksum(std::span<const char> bytes) {
    std::uint64_t hash = 0xcbf29ce484222325ull;  // FNV-1a 64: offset basis and prime
    for (const char c : bytes) {
        hash ^= static_cast<unsigned char>(c);
        hash *= 0x100000001b3ull;
    }
    return hash;
}

void check_restored_state(const Model& model) {
    const auto bytes = model.bytes();
    for (const auto& v : model.table().variables()) check_variable(v, bytes);
    model.validate();
    model.check_state();
}

}  // namespace fmu
