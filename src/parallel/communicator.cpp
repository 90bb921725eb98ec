#include "parallel/communicator.hpp"

#include <stdexcept>
#include <string>

#if ROULEAU_HAS_MPI
#include <mpi.h>
#endif

namespace rouleau {

#if ROULEAU_HAS_MPI
namespace {
void check(int status, const char* call) {
  if (status != MPI_SUCCESS) throw std::runtime_error(std::string("rouleau::Communicator: ") + call + " failed");
}
}  // namespace

bool Communicator::has_mpi() { return true; }

Communicator Communicator::world() {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) throw std::logic_error("rouleau::Communicator::world: MPI is not initialized");
  int rank = 0, size = 1;
  check(MPI_Comm_rank(MPI_COMM_WORLD, &rank), "MPI_Comm_rank");
  check(MPI_Comm_size(MPI_COMM_WORLD, &size), "MPI_Comm_size");
  return Communicator(rank, size);
}

double Communicator::sum(double value) const {
  double total = 0.0;
  check(MPI_Allreduce(&value, &total, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD), "MPI_Allreduce");
  return total;
}

long long Communicator::sum(long long value) const {
  long long total = 0;
  check(MPI_Allreduce(&value, &total, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD), "MPI_Allreduce");
  return total;
}

void Communicator::sum(double* values, int count) const {
  check(MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD), "MPI_Allreduce");
}

double Communicator::max(double value) const {
  double largest = 0.0;
  check(MPI_Allreduce(&value, &largest, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
  return largest;
}

void Communicator::bitwise_or(unsigned* values, const int count) const {
  check(MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_UNSIGNED, MPI_BOR, MPI_COMM_WORLD), "MPI_Allreduce");
}

std::vector<int> Communicator::rank_of_smallest(const std::vector<double>& values) const {
  struct ValueAndRank {
    double value;
    int rank;
  };
  std::vector<ValueAndRank> mine(values.size()), smallest(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) mine[i] = {values[i], rank_};
  check(MPI_Allreduce(mine.data(), smallest.data(), static_cast<int>(values.size()), MPI_DOUBLE_INT, MPI_MINLOC,
                      MPI_COMM_WORLD),
        "MPI_Allreduce");
  std::vector<int> ranks(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) ranks[i] = smallest[i].rank;
  return ranks;
}

struct PendingExchange::Requests {
  std::vector<MPI_Request> handles;
};

void PendingExchange::wait() {
  if (!requests_ || requests_->handles.empty()) return;
  check(MPI_Waitall(static_cast<int>(requests_->handles.size()), requests_->handles.data(), MPI_STATUSES_IGNORE),
        "MPI_Waitall");
  requests_->handles.clear();
}

PendingExchange Communicator::start_exchange(const std::vector<int>& ranks,
                                             const std::vector<std::vector<double>>& send,
                                             std::vector<std::vector<double>>& recv) const {
  const std::size_t n = ranks.size();
  if (send.size() != n || recv.size() != n)
    throw std::invalid_argument("rouleau::Communicator::exchange: one send and one receive buffer per rank");
  PendingExchange pending;
  std::vector<MPI_Request>& requests = pending.requests_->handles;
  requests.assign(2 * n, MPI_REQUEST_NULL);
  constexpr int tag = 7;
  for (std::size_t k = 0; k < n; ++k)
    check(MPI_Irecv(recv[k].data(), static_cast<int>(recv[k].size()), MPI_DOUBLE, ranks[k], tag, MPI_COMM_WORLD,
                    &requests[k]),
          "MPI_Irecv");
  for (std::size_t k = 0; k < n; ++k)
    check(MPI_Isend(send[k].data(), static_cast<int>(send[k].size()), MPI_DOUBLE, ranks[k], tag, MPI_COMM_WORLD,
                    &requests[n + k]),
          "MPI_Isend");
  return pending;
}

void Communicator::barrier() const { check(MPI_Barrier(MPI_COMM_WORLD), "MPI_Barrier"); }

namespace {
// MPI_Gatherv of `mine` (type T as `type`) onto root, rank after rank.
template <class T>
std::vector<T> gather_on_root(const std::vector<T>& mine, int root, int rank, int size, MPI_Datatype type) {
  const int count = static_cast<int>(mine.size());
  std::vector<int> counts(rank == root ? size : 0), offsets;
  check(MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, root, MPI_COMM_WORLD), "MPI_Gather");
  std::vector<T> all;
  if (rank == root) {
    offsets.assign(size, 0);
    for (int r = 1; r < size; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
    all.resize(static_cast<std::size_t>(offsets[size - 1]) + counts[size - 1]);
  }
  check(MPI_Gatherv(mine.data(), count, type, all.data(), counts.data(), offsets.data(), type, root, MPI_COMM_WORLD),
        "MPI_Gatherv");
  return all;
}
}  // namespace

std::vector<double> Communicator::gather(const std::vector<double>& mine, int root) const {
  return gather_on_root(mine, root, rank_, size_, MPI_DOUBLE);
}

std::vector<int> Communicator::gather(const std::vector<int>& mine, int root) const {
  return gather_on_root(mine, root, rank_, size_, MPI_INT);
}

std::vector<double> Communicator::scatter(const std::vector<double>& all, const std::vector<int>& counts,
                                          int root) const {
  if (static_cast<int>(counts.size()) != size_)
    throw std::invalid_argument("rouleau::Communicator::scatter: one count per rank");
  std::vector<int> offsets(size_, 0);
  for (int r = 1; r < size_; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<double> mine(counts[rank_]);
  check(MPI_Scatterv(all.data(), counts.data(), offsets.data(), MPI_DOUBLE, mine.data(), counts[rank_], MPI_DOUBLE,
                     root, MPI_COMM_WORLD),
        "MPI_Scatterv");
  return mine;
}

#else  // one rank, no MPI

bool Communicator::has_mpi() { return false; }
Communicator Communicator::world() { return Communicator(0, 1); }
double Communicator::sum(double value) const { return value; }
long long Communicator::sum(long long value) const { return value; }
double Communicator::max(double value) const { return value; }
void Communicator::sum(double*, int) const {}
void Communicator::bitwise_or(unsigned*, int) const {}
std::vector<int> Communicator::rank_of_smallest(const std::vector<double>& values) const {
  return std::vector<int>(values.size(), 0);
}
struct PendingExchange::Requests {};

void PendingExchange::wait() {}

PendingExchange Communicator::start_exchange(const std::vector<int>& ranks, const std::vector<std::vector<double>>&,
                                             std::vector<std::vector<double>>&) const {
  if (!ranks.empty()) throw std::logic_error("rouleau::Communicator::exchange: no other rank in a build without MPI");
  return PendingExchange();
}
void Communicator::barrier() const {}
std::vector<double> Communicator::gather(const std::vector<double>& mine, int) const { return mine; }
std::vector<int> Communicator::gather(const std::vector<int>& mine, int) const { return mine; }
std::vector<double> Communicator::scatter(const std::vector<double>& all, const std::vector<int>&, int) const {
  return all;
}

#endif

PendingExchange::PendingExchange() : requests_(std::make_unique<Requests>()) {}
PendingExchange::PendingExchange(PendingExchange&&) noexcept = default;
PendingExchange& PendingExchange::operator=(PendingExchange&& other) noexcept {
  if (this != &other) {
    wait();
    requests_ = std::move(other.requests_);
  }
  return *this;
}
PendingExchange::~PendingExchange() {
  try {
    wait();
  } catch (...) {  // a failed MPI_Waitall in a destructor: MPI_ERRORS_ARE_FATAL stops the run anyway
  }
}

void Communicator::exchange(const std::vector<int>& ranks, const std::vector<std::vector<double>>& send,
                            std::vector<std::vector<double>>& recv) const {
  start_exchange(ranks, send, recv).wait();
}

}  // namespace rouleau
