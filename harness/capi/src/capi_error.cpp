#include "capi_error.hpp"

#include <cstring>
#include <new>

#include "engine/interrupt.hpp"

namespace pvatt_capi {

namespace {
thread_local std::string last_error;
}  // namespace

void set_last_error(const std::string& message) {
    try {
        last_error = message;
    } catch (...) {
        last_error.clear();  // out of memory for the message: an empty one rather than none
    }
}

void copy_text(const std::string& text, char* buffer, std::size_t size, std::size_t* needed) {
    if (needed) *needed = text.size() + 1;
    if (!buffer || size < text.size() + 1)
        throw BufferTooSmall("the buffer of " + std::to_string(size) + " bytes is too small for " +
                             std::to_string(text.size() + 1));
    std::memcpy(buffer, text.c_str(), text.size() + 1);
}

pvatt_status status_of_current_exception() noexcept {
    try {
        throw;
    } catch (const cosim::Interrupted& e) {
        set_last_error(std::string("interrupted: ") + e.what());
        return PVATT_INTERRUPTED;
    } catch (const CallbackFailed& e) {
        set_last_error(e.what());
        return PVATT_CALLBACK_FAILED;
    } catch (const InvalidArgument& e) {
        set_last_error(e.what());
        return PVATT_INVALID_ARGUMENT;
    } catch (const WrongState& e) {
        set_last_error(e.what());
        return PVATT_WRONG_STATE;
    } catch (const BufferTooSmall& e) {
        set_last_error(e.what());
        return PVATT_BUFFER_TOO_SMALL;
    } catch (const std::bad_alloc&) {
        set_last_error("out of memory");
        return PVATT_ERROR;
    } catch (const std::exception& e) {
        set_last_error(e.what());
        return PVATT_ERROR;
    } catch (...) {
        set_last_error("an unknown C++ exception");
        return PVATT_ERROR;
    }
}

}  // namespace pvatt_capi

extern "C" const char* pvatt_last_error(void) {
    return pvatt_capi::last_error.c_str();
}
