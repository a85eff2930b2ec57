// What the loader accepts from an FMU at most. An .fmu comes from anywhere: without bounds a small
// archive can fill the disk (a "zip bomb") and a short modelDescription.xml can ask for billions of
// event indicators. Every limit is named in the error it raises; README "Errors" lists the defaults.
#pragma once

#include <cstddef>
#include <cstdint>

namespace fmi_loader {

struct Limits {
    // The archive.
    std::uint64_t max_entries = 10'000;
    std::uint64_t max_entry_bytes = std::uint64_t{1} << 30;  // 1 GiB uncompressed per entry
    std::uint64_t max_total_bytes = std::uint64_t{2} << 30;  // 2 GiB uncompressed in all
    // Uncompressed over compressed size, checked for entries of at least ratio_min_bytes: deflate
    // reaches ~1000:1 only on runs of one byte, while binaries and XML stay below ~20:1.
    double max_compression_ratio = 200.0;
    std::uint64_t ratio_min_bytes = std::uint64_t{1} << 20;
    // modelDescription.xml.
    std::uint64_t max_description_bytes = std::uint64_t{64} << 20;  // 64 MiB
    std::size_t max_variables = 1'000'000;
    std::size_t max_event_indicators = 1'000'000;
};

// Set from a signal handler (async-signal-safe: a lock-free atomic store) to make a running extraction
// stop at its next block and remove what it wrote.
void request_cancel() noexcept;
bool cancel_requested() noexcept;
void clear_cancel() noexcept;

}  // namespace fmi_loader
