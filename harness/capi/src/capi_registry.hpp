// Which handles are open: every entry point checks the handle it is given against this registry, so a
// closed system, a freed simulation or a result freed twice is refused with a status and a message
// instead of being used (as the FMI layer in fmus/ does for its instances). A handle is refused once
// freed; an address the allocator hands out again for a new handle is that new handle's.
//
// Re-entrancy: a callback component runs inside pvatt_run or pvatt_advance_to (on the run's thread).
// The calls that would block on the run the callback is part of, or nest a run in it, are refused from
// there (in_callback()), and a system closed while a run or a simulation uses it is freed when the
// last of them ends (pvatt_system::users).
#pragma once

#include <cstddef>
#include <string>

struct pvatt_system;
struct pvatt_simulation;
struct pvatt_result;

namespace pvatt_capi {

void register_handle(const pvatt_system* h);
void register_handle(const pvatt_simulation* h);
void register_handle(const pvatt_result* h);
// False when the handle was not open (already freed, or never handed out).
bool unregister_handle(const pvatt_simulation* h);
bool unregister_handle(const pvatt_result* h);

// The handle itself when it is open; InvalidArgument naming `what` when it is NULL or not open.
pvatt_system& open_system(const pvatt_system* h);
pvatt_simulation& open_simulation(const pvatt_simulation* h);
const pvatt_result& open_result(const pvatt_result* h);
bool is_open(const pvatt_system* h);
bool is_open(const pvatt_simulation* h);
bool is_open(const pvatt_result* h);

// A run or a simulation using a system: the system stays allocated until the last user releases it,
// even when pvatt_system_close comes first (from a callback, say).
void acquire(pvatt_system* h);
void release(pvatt_system* h);
// pvatt_system_close: refused for a handle not open (false); frees it now or at its last release.
bool close_system(pvatt_system* h);

// Inside a callback component on this thread (depth counted: a callback may call another run's API).
bool in_callback();
class CallbackScope {
public:
    CallbackScope();
    ~CallbackScope();
    CallbackScope(const CallbackScope&) = delete;
    CallbackScope& operator=(const CallbackScope&) = delete;
};
// WrongState naming `function` when called from inside a callback component.
void refuse_in_callback(const char* function);

}  // namespace pvatt_capi
