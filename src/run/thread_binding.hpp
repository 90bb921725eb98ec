#pragma once
// Where the host's OpenMP threads run.
//
// A run's step is hundreds of short parallel loops, each ending at a barrier that waits for
// the slowest thread. Threads the operating system may move are moved onto the same core as
// other work, and then every loop waits. Measured on a 2-core machine, 2 threads, beside one
// busy single-threaded process (docs/running.md): a step of the four-cell stack took 2.1
// times its idle time with the threads bound one per core, 4.1 times unbound; two runs side
// by side took 17.3 s each bound, 31.9 s unbound. So a run binds its threads unless it is
// told how to place them:
// - OMP_PROC_BIND, OMP_PLACES, GOMP_CPU_AFFINITY or KMP_AFFINITY set: the OpenMP runtime
//   places them as they say (OMP_PROC_BIND=false leaves them free);
// - started by an MPI launcher as several ranks: the launcher's binding holds;
// - one thread, or more threads than the process may use CPUs: nothing is bound.
// Otherwise thread t goes to one CPU of the process's affinity mask, spread over distinct
// cores first (one hardware thread per core, then their siblings).
#include <string>
#include <vector>

namespace rouleau {

// The CPUs thread t = 0 … threads−1 is bound to, one each, spread over the `cpus` allowed
// (their ids) whose core is core_of[k] for cpus[k] (a core's first CPU in the list goes
// before its siblings); empty when threads < 2 or threads > cpus.size().
std::vector<int> spread_threads_over_cores(int threads, const std::vector<int>& cpus, const std::vector<int>& core_of);

// Binds the host's `threads` OpenMP threads (the pool the parallel loops run on) as above,
// unless the environment or an MPI launcher decides; returns the CPUs used (empty when it
// bound nothing). Call once, after the runtime's thread pool exists.
std::vector<int> bind_host_threads(int threads);

// One line for the run's log: how the host threads are placed now, read from each thread's
// own affinity ("host threads bound one per CPU: 0, 1", or how to bind them).
std::string describe_host_thread_binding(int threads);

}  // namespace rouleau
