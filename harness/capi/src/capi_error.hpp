// How the C API turns C++ failures into a status and a message: every entry point runs its body
// through guarded(), which catches everything (no exception crosses the C boundary) and records the
// message as the calling thread's last error.
#pragma once

#include <stdexcept>
#include <string>

#include "pvatt/cosim.h"

namespace pvatt_capi {

// A caller's mistake: a null pointer, an unknown name, a value of the wrong type.
class InvalidArgument : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A callback component returned non-zero.
class CallbackFailed : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Asked of a simulation in a state that cannot do it (finished, or backwards in time).
class WrongState : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A caller's buffer cannot hold what was asked.
class BufferTooSmall : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Records the message as this thread's last error.
void set_last_error(const std::string& message);

// The status of the exception being handled (call from a catch block); records its message.
pvatt_status status_of_current_exception() noexcept;

template <class F>
pvatt_status guarded(F&& body) noexcept {
    try {
        body();
        return PVATT_OK;
    } catch (...) {
        return status_of_current_exception();
    }
}

// Throws InvalidArgument naming `what` when p is null.
template <class T>
T* required(T* p, const char* what) {
    if (!p) throw InvalidArgument(std::string(what) + " is NULL");
    return p;
}

// Copies text and its terminating zero into a caller's buffer of `size` bytes; *needed (when not null)
// gets the size needed. BufferTooSmall when it does not fit.
void copy_text(const std::string& text, char* buffer, std::size_t size, std::size_t* needed);

}  // namespace pvatt_capi
