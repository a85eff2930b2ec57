#include "capi_registry.hpp"

#include <mutex>
#include <unordered_set>

#include "capi_error.hpp"
#include "capi_handles.hpp"

namespace pvatt_capi {

namespace {

struct Registry {
    std::mutex mutex;
    std::unordered_set<const void*> systems, simulations, results;
};
Registry& registry() {
    static Registry r;
    return r;
}

thread_local int callback_depth = 0;

void add(std::unordered_set<const void*> Registry::*set, const void* h) {
    auto& r = registry();
    std::lock_guard lock(r.mutex);
    (r.*set).insert(h);
}
bool remove(std::unordered_set<const void*> Registry::*set, const void* h) {
    auto& r = registry();
    std::lock_guard lock(r.mutex);
    return (r.*set).erase(h) != 0;
}
bool contains(std::unordered_set<const void*> Registry::*set, const void* h) {
    auto& r = registry();
    std::lock_guard lock(r.mutex);
    return h && (r.*set).contains(h);
}
void refuse(const void* h, const char* what) {
    if (!h) throw InvalidArgument(std::string(what) + " is NULL");
    throw InvalidArgument(std::string(what) +
                          " is not open (closed or freed already, or never returned by the library)");
}

}  // namespace

void register_handle(const pvatt_system* h) {
    add(&Registry::systems, h);
}
void register_handle(const pvatt_simulation* h) {
    add(&Registry::simulations, h);
}
void register_handle(const pvatt_result* h) {
    add(&Registry::results, h);
}
bool unregister_handle(const pvatt_simulation* h) {
    return remove(&Registry::simulations, h);
}
bool unregister_handle(const pvatt_result* h) {
    return remove(&Registry::results, h);
}

bool is_open(const pvatt_system* h) {
    return contains(&Registry::systems, h);
}
bool is_open(const pvatt_simulation* h) {
    return contains(&Registry::simulations, h);
}
bool is_open(const pvatt_result* h) {
    return contains(&Registry::results, h);
}

pvatt_system& open_system(const pvatt_system* h) {
    if (!is_open(h)) refuse(h, "system");
    return *const_cast<pvatt_system*>(h);
}
pvatt_simulation& open_simulation(const pvatt_simulation* h) {
    if (!is_open(h)) refuse(h, "simulation");
    return *const_cast<pvatt_simulation*>(h);
}
const pvatt_result& open_result(const pvatt_result* h) {
    if (!is_open(h)) refuse(h, "result");
    return *h;
}

void acquire(pvatt_system* h) {
    auto& r = registry();
    std::lock_guard lock(r.mutex);
    ++h->users;
}

void release(pvatt_system* h) {
    bool free = false;
    {
        auto& r = registry();
        std::lock_guard lock(r.mutex);
        free = --h->users == 0 && h->closed;
    }
    if (free) delete h;
}

bool close_system(pvatt_system* h) {
    bool free = false;
    {
        auto& r = registry();
        std::lock_guard lock(r.mutex);
        if (!h || r.systems.erase(h) == 0) return false;
        h->closed = true;
        free = h->users == 0;
    }
    if (free) delete h;
    return true;
}

bool in_callback() {
    return callback_depth > 0;
}
CallbackScope::CallbackScope() {
    ++callback_depth;
}
CallbackScope::~CallbackScope() {
    --callback_depth;
}

void refuse_in_callback(const char* function) {
    if (in_callback())
        throw WrongState(std::string(function) +
                         " was called from inside a callback component, which runs inside a run: it may not open a "
                         "system, nor start, advance or free a run (pvatt_interrupt stops the run it is in)");
}

}  // namespace pvatt_capi
