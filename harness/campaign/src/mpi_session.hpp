// MPI for a campaign, only when the process was started by an MPI launcher (mpirun, srun): a plain
// `cosim campaign` never initialises MPI, so the single-process path needs no MPI runtime at all.
// Without PVATT_MPI in the build, a launch with several ranks is refused (each would run everything).
#pragma once

namespace campaign {

class MpiSession {
public:
    MpiSession();
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;
    int rank() const { return rank_; }
    int size() const { return size_; }
    // Ends every rank at once (a fatal error on any rank while the others wait for it).
    [[noreturn]] void abort(int code) const;

private:
    bool initialised_ = false;
    int rank_ = 0, size_ = 1;
};

}  // namespace campaign
