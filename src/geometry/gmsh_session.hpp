#pragma once
// One use of the Gmsh API at a time. Gmsh keeps a single global state and is not
// thread-safe, so every part of rouleau that calls Gmsh does it inside a GmshSession: it
// holds a process-wide mutex for its lifetime, initializes Gmsh (no configuration files
// read, nothing printed, one thread, fixed random seed, so that meshes are the same run
// after run) and finalizes it at the end, so no model or option outlives the session.
// Host-only: includes no Kokkos header.
#include <mutex>
#include <string>

namespace rouleau {

class GmshSession {
 public:
  GmshSession();
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

  // The version of the Gmsh library linked in ("4.8.4"), as Gmsh reports it. Do not call
  // it while this thread holds a session.
  static std::string library_version();

 private:
  std::unique_lock<std::mutex> lock_;
};

// The message of an exception thrown by the Gmsh API: Gmsh 4.8 throws std::string (its
// last error), other versions std::exception. Call it from within a catch block.
std::string current_gmsh_error();

}  // namespace rouleau
