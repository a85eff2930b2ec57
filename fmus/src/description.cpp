#include "fmu/description.hpp"

#include <charconv>
#include <cinttypes>
#include <cstdio>
#include <utility>

#include "fmu/value_access.hpp"

namespace fmu {

std::string format_real(double value) {
    // Shortest text that reads back to the same double (2.5, not 2.5000000000000000).
    char buf[32];
    const auto result = std::to_chars(buf, buf + sizeof buf, value);
    return std::string(buf, result.ptr);
}

std::string start_text(const Variable& v, std::span<const std::byte> defaults) {
    switch (v.type) {
        case ValueType::Real:
            return format_real(read_real(defaults, v));
        case ValueType::Integer:
        case ValueType::Enumeration:
            return std::to_string(read_integer(defaults, v));
        case ValueType::Boolean:
            return read_boolean(defaults, v) ? "true" : "false";
        case ValueType::String:
            return std::string(read_string(defaults, v));
    }
    return {};
}

std::string description_fingerprint(const Model& model) {
    auto defaults = model.clone();
    defaults->reset_to_defaults();
    const auto bytes = std::as_const(*defaults).bytes();
    const auto& info = model.info();
    std::string text;
    auto field = [&](std::string_view s) {
        text += s;
        text += '\x1f';  // unit separator: no field text can fake another field's boundary
    };
    field(info.model_identifier);
    field(info.model_name);
    field(info.description);
    field(info.version);
    field(format_real(info.default_experiment.start_time));
    field(format_real(info.default_experiment.stop_time));
    field(format_real(info.default_experiment.tolerance));
    field(format_real(info.default_experiment.step_size));
    field(std::to_string(model.event_indicator_count()));
    for (const auto& v : model.table().variables()) {
        field(v.name);
        field(std::to_string(v.value_reference));
        field(to_string(v.type));
        field(to_string(v.causality));
        field(to_string(v.variability));
        field(to_string(v.initial));
        field(v.unit);
        field(v.description);
        field(v.has_start() ? start_text(v, bytes) : "-");
        field(v.min ? format_real(*v.min) : "-");
        field(v.max ? format_real(*v.max) : "-");
        field(v.nominal ? format_real(*v.nominal) : "-");
        field(v.derivative_of ? std::to_string(*v.derivative_of) : "-");
        if (v.dependencies)
            for (auto d : *v.dependencies) field(std::to_string(d));
        field(v.declared_type);
        for (const auto& item : v.items) {
            field(item.name);
            field(std::to_string(item.value));
        }
        text += '\x1e';
    }
    return text;
}

std::string description_guid(const Model& model) {
    // Two FNV-1a 64-bit passes with different offset bases give 128 bits; not cryptographic, only
    // meant to change whenever the description changes.
    const std::string text = description_fingerprint(model);
    auto fnv = [&](std::uint64_t hash) {
        for (unsigned char c : text) {
            hash ^= c;
            hash *= 0x100000001b3ull;
        }
        return hash;
    };
    const std::uint64_t a = fnv(0xcbf29ce484222325ull);
    const std::uint64_t b = fnv(0x84222325cbf29ce4ull);
    char buf[48];
    std::snprintf(buf, sizeof buf, "{%08" PRIx64 "-%04" PRIx64 "-%04" PRIx64 "-%04" PRIx64 "-%012" PRIx64 "}",
                  static_cast<std::uint64_t>(a >> 32), static_cast<std::uint64_t>((a >> 16) & 0xffff),
                  static_cast<std::uint64_t>(a & 0xffff), static_cast<std::uint64_t>(b >> 48),
                  static_cast<std::uint64_t>(b & 0xffffffffffffull));
    return buf;
}

}  // namespace fmu
