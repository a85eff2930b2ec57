#include "mpi_session.hpp"

#include <cstdlib>
#include <string>

#include "campaign_error.hpp"

#ifdef PVATT_MPI
#include <mpi.h>
#endif

namespace campaign {

namespace {

// Ranks in the job as the launchers announce them: Open MPI's mpirun, PMI (MPICH, Slurm's srun
// --mpi=pmi2), PMIx (Slurm's srun --mpi=pmix, Open MPI 4 under Slurm).
int launched_ranks() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
        if (const char* v = std::getenv(name)) return std::atoi(v);
    return std::getenv("PMIX_RANK") ? 2 : 0;  // PMIx without a size: take it as an MPI launch
}

}  // namespace

MpiSession::MpiSession() {
    const int launched = launched_ranks();
    if (launched == 0) return;
#ifdef PVATT_MPI
    // The main thread talks to MPI; on rank 0 a second thread runs simulations (FUNNELED).
    int provided = 0;
    if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
        throw CampaignError("MPI_Init_thread failed");
    initialised_ = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    if (provided < MPI_THREAD_FUNNELED && size_ > 1) {
        MPI_Finalize();
        initialised_ = false;
        throw CampaignError("the MPI library offers no MPI_THREAD_FUNNELED support, which rank 0 needs");
    }
#else
    if (launched > 1)
        throw CampaignError("this cosim was built without MPI (-DPVATT_MPI=OFF): under an MPI launcher each of the " +
                            std::to_string(launched) + " ranks would run the whole campaign");
#endif
}

MpiSession::~MpiSession() {
#ifdef PVATT_MPI
    if (initialised_) MPI_Finalize();
#endif
}

void MpiSession::abort(int code) const {
#ifdef PVATT_MPI
    if (initialised_) MPI_Abort(MPI_COMM_WORLD, code);
#endif
    std::exit(code);
}

}  // namespace campaign
