#pragma once
// The ranks of a run and what they say to each other (docs/mpi.md): MPI_COMM_WORLD when the
// build has MPI (ROULEAU_HAS_MPI, CMake option ROULEAU_MPI), otherwise one rank on its own.
// Host-only: no Kokkos; the buffers are host memory (device data is staged by the caller,
// distributed/node_halo.hpp).
#include <memory>
#include <vector>

namespace rouleau {

// Point-to-point messages under way (Communicator::start_exchange): wait() returns when
// every one has arrived and been sent; the destructor waits for any not waited for. The
// send and receive buffers must stay in place until then.
class PendingExchange {
 public:
  PendingExchange();
  PendingExchange(PendingExchange&&) noexcept;
  PendingExchange& operator=(PendingExchange&&) noexcept;
  ~PendingExchange();
  void wait();

 private:
  friend class Communicator;
  struct Requests;  // MPI_Request handles (none in a build without MPI)
  std::unique_ptr<Requests> requests_;
};

class Communicator {
 public:
  // All ranks of the run (MPI_COMM_WORLD; MPI must be initialized), or the single rank of
  // a build without MPI.
  static Communicator world();
  // Whether this build talks MPI at all.
  static bool has_mpi();

  int rank() const { return rank_; }
  int size() const { return size_; }

  // The sums and maximum over all ranks (MPI_Allreduce); on one rank, the value.
  double sum(double value) const;
  long long sum(long long value) const;
  double max(double value) const;
  // values[i] ← Σ_ranks values[i], i < count, in place (one MPI_Allreduce).
  void sum(double* values, int count) const;
  // values[i] ← the bitwise OR over the ranks of values[i], i < count, in place.
  void bitwise_or(unsigned* values, int count) const;
  // For each i, the rank whose values[i] is the smallest (the lowest such rank on ties):
  // one MPI_Allreduce with MPI_MINLOC. On one rank, zeros.
  std::vector<int> rank_of_smallest(const std::vector<double>& values) const;

  // Point-to-point, all at once: send[k] goes to ranks[k], and recv[k] (sized by the
  // caller to what ranks[k] sends) is filled from ranks[k]. Returns when all are done.
  void exchange(const std::vector<int>& ranks, const std::vector<std::vector<double>>& send,
                std::vector<std::vector<double>>& recv) const;
  // The same, started: returns with the messages posted (MPI_Irecv, MPI_Isend), so the
  // caller can compute while they travel, then wait()s on the result.
  PendingExchange start_exchange(const std::vector<int>& ranks, const std::vector<std::vector<double>>& send,
                                 std::vector<std::vector<double>>& recv) const;

  // Gathers every rank's `mine` on `root`, rank after rank (MPI_Gatherv); empty elsewhere.
  std::vector<double> gather(const std::vector<double>& mine, int root) const;
  std::vector<int> gather(const std::vector<int>& mine, int root) const;
  // The reverse: rank r receives its `counts[r]` entries of `all` (read on `root` only;
  // counts on every rank).
  std::vector<double> scatter(const std::vector<double>& all, const std::vector<int>& counts, int root) const;

  void barrier() const;

 private:
  Communicator(int rank, int size) : rank_(rank), size_(size) {}
  int rank_ = 0, size_ = 1;
};

}  // namespace rouleau
