#pragma once
// The instances alive in this process (one registry per FMU binary). A handle the host passes in is used
// only if it is one of them, so a null, freed or foreign pointer gives an error status instead of a crash.
//
// Every FMI call asks; the answer must not cost a lock each time (the standard has one thread call one
// instance, and a system calls its few instances millions of times). The last few handles found live are
// kept in atomic slots read without the lock; instantiation and freeing take the lock, and freeing clears
// the handle's slot before the instance is deleted, so a slot never names a freed instance. (A host that
// frees an instance while another of its threads still calls it breaks the standard's rule; no check made
// before the call can catch that, with or without a lock.)
#include <array>
#include <atomic>
#include <cstddef>
#include <mutex>
#include <unordered_set>

namespace fmu {

class LiveInstances {
public:
    void insert(const void* c) {
        const std::lock_guard lock(mutex_);
        live_.insert(c);
    }
    /// False when c was not live (nothing to free).
    bool erase(const void* c) {
        const std::lock_guard lock(mutex_);
        if (live_.erase(c) == 0) return false;
        for (auto& slot : recent_)
            if (slot.load(std::memory_order_relaxed) == c) slot.store(nullptr, std::memory_order_release);
        return true;
    }
    bool contains(const void* c) {
        for (const auto& slot : recent_)
            if (slot.load(std::memory_order_acquire) == c) return true;
        const std::lock_guard lock(mutex_);
        if (!live_.contains(c)) return false;
        recent_[next_].store(c, std::memory_order_release);
        next_ = (next_ + 1) % kRecent;
        return true;
    }

private:
    static constexpr std::size_t kRecent = 4;  // a system's instances of one FMU: usually one
    std::mutex mutex_;
    std::unordered_set<const void*> live_;
    std::array<std::atomic<const void*>, kRecent> recent_{};  // null or live
    std::size_t next_ = 0;                                    // under mutex_
};

}  // namespace fmu
