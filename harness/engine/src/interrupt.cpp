#include "engine/interrupt.hpp"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>

#include "fmi_loader/limits.hpp"

namespace cosim {

namespace {

namespace fs = std::filesystem;

std::atomic<int> received{0};
std::once_flag installed;

// Declared before private_temp so that it outlives it: the destructor below takes it.
std::mutex private_temp_mutex;

// Removes `path` and everything in it. The main thread may be removing the extraction folders inside it at
// the same time (a run unwinding from the first signal when the second aborts it): remove_all stops at the
// first entry that vanished under it and leaves the rest, so it is repeated until the folder is gone (an
// extraction under way stops at its next entry once a signal has been received: fmu_archive.cpp).
void remove_folder(const fs::path& path) {
    std::error_code ec;
    for (int attempt = 0; attempt < 100 && fs::exists(path, ec); ++attempt) fs::remove_all(path, ec);
}

// The private temporary folder of use_private_temp_directory(): removed when the process exits
// normally (a static's destructor) and by the signal thread on an abort, one at a time.
struct PrivateTemp {
    fs::path path;
    ~PrivateTemp() {
        std::lock_guard lock(private_temp_mutex);
        if (!path.empty()) remove_folder(path);
    }
};
PrivateTemp private_temp;

const char* signal_name(int signal) {
    return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : signal == SIGHUP ? "SIGHUP" : "a signal";
}

sigset_t stop_signals() {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    sigaddset(&set, SIGHUP);
    return set;
}

// Runs in ordinary thread context (sigwait), not in a signal handler: removing folders is safe here.
void signal_loop(sigset_t set) {
    for (;;) {
        int signal = 0;
        if (::sigwait(&set, &signal) != 0) continue;
        int expected = 0;
        if (received.compare_exchange_strong(expected, signal)) {
            fmi_loader::request_cancel();
            continue;
        }
        std::fprintf(stderr, "cosim: second signal (%s): aborting without unwinding (exit code %d)\n",
                     signal_name(signal), aborted_exit_code);
        {
            std::lock_guard lock(private_temp_mutex);
            if (!private_temp.path.empty()) remove_folder(private_temp.path);
        }
        std::_Exit(aborted_exit_code);
    }
}

// The private folder's name: cosim_<host>_<pid>_XXXXXX. The host, so that a temporary directory shared between
// machines is never swept for another machine's processes; its characters outside [A-Za-z0-9.-] become '-'.
std::string private_temp_prefix() {
    char host[256] = {};
    if (::gethostname(host, sizeof host - 1) != 0) host[0] = '\0';
    std::string name;
    for (const char* c = host; *c != '\0'; ++c) {
        const bool plain =
            (*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z') || (*c >= '0' && *c <= '9') || *c == '.' || *c == '-';
        name.push_back(plain ? *c : '-');
    }
    return "cosim_" + name + "_";
}

// A process killed with SIGKILL (an out-of-memory kill, a batch system's time limit) cannot remove its private
// folder: each such kill left its FMUs' extraction folders behind, 16 MB for leo_orbit, per MPI rank. A new
// process removes the folders of this host whose process is gone (kill(pid, 0) says ESRCH), its own user's only
// (the folders are 0700). A process id taken again by another process keeps its folder until that one ends.
void sweep_stale_private_temps(const fs::path& temp, const std::string& prefix) {
    std::error_code ec;
    for (fs::directory_iterator it(temp, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.compare(0, prefix.size(), prefix) != 0) continue;
        const std::size_t digits_end = name.find('_', prefix.size());
        if (digits_end == std::string::npos || digits_end == prefix.size() || digits_end - prefix.size() > 9) continue;
        const std::string digits = name.substr(prefix.size(), digits_end - prefix.size());
        if (digits.find_first_not_of("0123456789") != std::string::npos) continue;
        const pid_t pid = static_cast<pid_t>(std::stol(digits));
        if (pid <= 0 || pid == ::getpid() || ::kill(pid, 0) == 0 || errno != ESRCH) continue;
        std::error_code status_ec;
        if (!fs::is_directory(it->symlink_status(status_ec)) || status_ec) continue;  // never follow a link
        remove_folder(it->path());
    }
}

}  // namespace

Interrupted::Interrupted(int signal)
    : std::runtime_error(std::string("interrupted by ") + signal_name(signal)), signal_(signal) {}

void install_interrupt_handlers() {
    std::call_once(installed, [] {
        const sigset_t set = stop_signals();
        ::pthread_sigmask(SIG_BLOCK, &set, nullptr);
        std::thread(signal_loop, set).detach();
    });
}

void use_private_temp_directory() {
    std::lock_guard lock(private_temp_mutex);
    if (!private_temp.path.empty()) return;
    std::error_code ec;
    const fs::path temp = fs::temp_directory_path(ec);
    if (ec) return;  // no temporary directory: the extraction folders go where they did
    const std::string prefix = private_temp_prefix();
    sweep_stale_private_temps(temp, prefix);
    std::string pattern = (temp / (prefix + std::to_string(::getpid()) + "_XXXXXX")).string();
    if (::mkdtemp(pattern.data()) == nullptr) return;  // no private folder: the extraction folders go where they did
    private_temp.path = pattern;
    ::setenv("TMPDIR", pattern.c_str(), 1);
}

int interrupt_signal() noexcept {
    return received.load(std::memory_order_relaxed);
}

void throw_if_interrupted() {
    if (const int s = interrupt_signal()) throw Interrupted(s);
}

void sleep_until_or_interrupted(std::chrono::steady_clock::time_point due) {
    for (;;) {
        throw_if_interrupted();
        const auto now = std::chrono::steady_clock::now();
        if (now >= due) return;
        std::this_thread::sleep_for(std::min<std::chrono::steady_clock::duration>(due - now, wait_slice));
    }
}

void clear_interrupt() noexcept {
    received.store(0, std::memory_order_relaxed);
    fmi_loader::clear_cancel();
}

void record_interrupt(int signal) noexcept {
    received.store(signal, std::memory_order_relaxed);
    fmi_loader::request_cancel();
}

}  // namespace cosim
