#include "parallel/mpi_session.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>

#include <chrono>
#include <thread>

#if ROULEAU_HAS_MPI
#include <mpi.h>

#include <exception>
#endif

namespace rouleau {

namespace {
// This process's rank as the MPI launcher set it (OpenMPI, MPICH/Hydra, PMIx), or 0: what
// an error met before MPI is up (a bad case file, which every rank reads) goes by.
int rank_from_launcher() {
  for (const char* variable : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"})
    if (const char* value = std::getenv(variable)) return std::atoi(value);
  return 0;
}
}  // namespace

#if ROULEAU_HAS_MPI
MpiSession::MpiSession() {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (initialized) return;
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  started_ = true;
}

MpiSession::~MpiSession() {
  // Left by an error on several ranks: MPI stays up for the report, which then stops all
  // ranks (MPI_Finalize would wait for ranks that may never come).
  if (std::uncaught_exceptions() > 0 && running_on_several_ranks()) return;
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (started_ && !finalized) MPI_Finalize();
}

bool running_on_several_ranks() {
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  if (!initialized || finalized) return false;
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size > 1;
}

void let_the_first_rank_report() {
  int rank = rank_from_launcher();
  if (running_on_several_ranks()) MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank > 0) std::this_thread::sleep_for(std::chrono::seconds(2));
}

void stop_all_ranks(int exit_code) {
  if (running_on_several_ranks()) MPI_Abort(MPI_COMM_WORLD, exit_code);
}
#else
MpiSession::MpiSession() {
  // Started by mpirun as several ranks, a build without MPI would run the whole case that
  // many times into the same folder.
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
    if (const char* value = std::getenv(variable); value && std::atoi(value) > 1)
      throw std::runtime_error(std::string("rouleau: started as ") + value +
                               " MPI ranks, but this build has no MPI (configure with -DROULEAU_MPI=ON)");
}
MpiSession::~MpiSession() {}
bool running_on_several_ranks() { return false; }
void let_the_first_rank_report() {
  if (rank_from_launcher() > 0) std::this_thread::sleep_for(std::chrono::seconds(2));
}
void stop_all_ranks(int) {}
#endif

}  // namespace rouleau
