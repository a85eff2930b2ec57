#include "fmi_loader/loader_error.hpp"

#include <atomic>

#include "fmi_loader/limits.hpp"

namespace fmi_loader {

std::string_view to_string(LoaderErrc code) noexcept {
    switch (code) {
        case LoaderErrc::archive_open:
            return "archive_open";
        case LoaderErrc::unsafe_entry:
            return "unsafe_entry";
        case LoaderErrc::extract_io:
            return "extract_io";
        case LoaderErrc::xml_parse:
            return "xml_parse";
        case LoaderErrc::xml_invalid:
            return "xml_invalid";
        case LoaderErrc::dl_open:
            return "dl_open";
        case LoaderErrc::missing_symbol:
            return "missing_symbol";
        case LoaderErrc::limit:
            return "limit";
        case LoaderErrc::cancelled:
            return "cancelled";
        case LoaderErrc::unsupported:
            return "unsupported";
    }
    return "unknown";
}

namespace {
std::atomic<bool> cancel_flag{false};
static_assert(std::atomic<bool>::is_always_lock_free, "request_cancel() must be async-signal-safe");
}  // namespace

void request_cancel() noexcept {
    cancel_flag.store(true, std::memory_order_relaxed);
}
bool cancel_requested() noexcept {
    return cancel_flag.load(std::memory_order_relaxed);
}
void clear_cancel() noexcept {
    cancel_flag.store(false, std::memory_order_relaxed);
}

LoaderError::LoaderError(LoaderErrc code, const std::string& message)
    : std::runtime_error(std::string(to_string(code)) + ": " + message), code_(code) {}

}  // namespace fmi_loader
