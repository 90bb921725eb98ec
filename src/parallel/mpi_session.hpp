#pragma once
// MPI for the lifetime of an MpiSession (docs/mpi.md): `rouleau run` and the case drivers
// start it before Kokkos, so `mpirun -np N rouleau run case.toml` splits the fluid across
// N ranks, and a plain `rouleau run` is one rank. In a build without MPI it does nothing,
// but refuses (std::runtime_error) to run as one of several ranks an MPI launcher started.
// Only the main thread calls MPI (MPI_THREAD_FUNNELED: OpenMP threads run beside it).
// Host-only.
namespace rouleau {

class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

 private:
  bool started_ = false;  // this session initialized MPI (and finalizes it)
};

// Whether MPI is up with more than one rank (then an error on one rank must stop all).
bool running_on_several_ranks();
// An error that every rank meets (a divergence: its tests read the whole fluid; a bad case
// file, met before MPI is up) is reported once, by the first rank, which also writes the
// files: the others (by MPI's rank, or the launcher's before MPI is up) wait 2 s before
// reporting, and the first rank's stop_all_ranks() or exit ends them before that.
void let_the_first_rank_report();
// Stops every rank with `exit_code` (MPI_Abort) when there are several; returns otherwise.
// For an error that only some ranks may have met: the others would wait for them forever.
void stop_all_ranks(int exit_code);

}  // namespace rouleau
