#include "drivers.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>

#include "campaign_error.hpp"
#include "engine/interrupt.hpp"

#ifdef PVATT_MPI
#include <mpi.h>
#endif

namespace campaign {

RunQueue::RunQueue(long runs, const std::map<long, std::string>& done)
    : runs_(runs),
      size_(runs - static_cast<long>(std::count_if(
                       done.begin(), done.end(), [&](const auto& row) { return row.first >= 0 && row.first < runs; }))),
      done_(done) {}

long RunQueue::next() {
    std::lock_guard lock(mutex_);
    while (next_ < runs_ && done_.contains(next_)) ++next_;
    return next_ < runs_ ? next_++ : -1;
}

void RunQueue::clear() {
    std::lock_guard lock(mutex_);
    next_ = runs_;
}

void run_sequential(const CampaignSetup& setup, RunQueue& to_do, Collector& collector) {
    for (long index = to_do.next(); index >= 0; index = to_do.next()) {
        cosim::throw_if_interrupted();
        collector.accept(0, format_row(run_one(setup, index)));
    }
}

#ifdef PVATT_MPI

namespace {

constexpr int tag_row = 1;     // worker -> 0: a finished row, or an empty message meaning "ready"
constexpr int tag_assign = 2;  // 0 -> worker: a run index, or -1 meaning "stop"

}  // namespace

void run_distributed(const CampaignSetup& setup, RunQueue& queue, Collector& collector, int ranks) {
    std::mutex mutex;
    std::deque<std::string> local_rows;
    std::exception_ptr local_error;
    std::atomic<bool> local_done = false;
    auto next = [&]() -> long { return cosim::interrupt_signal() ? -1 : queue.next(); };
    // Rank 0 computes too: on a small machine a dispatcher that only waits would waste a core. It
    // never calls MPI; the main thread below does, and sleeps while there is nothing to do.
    std::thread local([&] {
        try {
            for (long index = next(); index >= 0; index = next()) {
                std::string row = format_row(run_one(setup, index));
                std::lock_guard lock(mutex);
                local_rows.push_back(std::move(row));
            }
        } catch (...) {
            std::lock_guard lock(mutex);
            local_error = std::current_exception();
        }
        local_done = true;
    });
    int stopped = 0;
    bool local_finished = false;  // the thread has ended and its last row is taken
    try {
        while (stopped < ranks - 1 || !local_finished) {
            cosim::throw_if_interrupted();
            bool busy = false;
            int flag = 0;
            MPI_Status status;
            MPI_Iprobe(MPI_ANY_SOURCE, tag_row, MPI_COMM_WORLD, &flag, &status);
            if (flag) {
                busy = true;
                int length = 0;
                MPI_Get_count(&status, MPI_CHAR, &length);
                std::string row(static_cast<std::size_t>(length), '\0');
                MPI_Recv(row.data(), length, MPI_CHAR, status.MPI_SOURCE, tag_row, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                if (!row.empty()) collector.accept(status.MPI_SOURCE, row);
                long index = next();
                MPI_Send(&index, 1, MPI_LONG, status.MPI_SOURCE, tag_assign, MPI_COMM_WORLD);
                if (index < 0) ++stopped;
            }
            std::deque<std::string> rows;
            {
                std::lock_guard lock(mutex);
                rows.swap(local_rows);
                if (local_error) std::rethrow_exception(local_error);
                // local_done is set after the last row was pushed under this lock: all rows are in `rows`.
                local_finished = local_done;
            }
            for (const auto& row : rows) collector.accept(0, row);
            busy = busy || !rows.empty();
            if (!busy) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
    } catch (...) {
        // The caller aborts the job; the local thread must not outlive its captures.
        queue.clear();
        local.join();
        throw;
    }
    local.join();
}

void serve_as_worker(const CampaignSetup& setup) {
    std::string row;  // empty: "ready"
    for (;;) {
        MPI_Send(row.data(), static_cast<int>(row.size()), MPI_CHAR, 0, tag_row, MPI_COMM_WORLD);
        long index = -1;
        MPI_Recv(&index, 1, MPI_LONG, 0, tag_assign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (index < 0) return;
        row = format_row(run_one(setup, index));
    }
}

#endif

}  // namespace campaign
