#include "geometry/gmsh_session.hpp"

#include <gmsh.h>

#include <exception>

namespace rouleau {

namespace {
std::mutex& gmsh_mutex() {
  static std::mutex mutex;
  return mutex;
}
// Read in the first session, under the mutex.
std::string& known_library_version() {
  static std::string version;
  return version;
}
}  // namespace

GmshSession::GmshSession() : lock_(gmsh_mutex()) {
  gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
  try {
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 1);  // errors only, into the logger
    gmsh::option::setNumber("General.NumThreads", 1);
    gmsh::option::setNumber("Mesh.MaxNumThreads1D", 1);
    gmsh::option::setNumber("Mesh.MaxNumThreads2D", 1);
    gmsh::option::setNumber("Mesh.MaxNumThreads3D", 1);
    gmsh::option::setNumber("Mesh.RandomSeed", 1);
    if (known_library_version().empty()) gmsh::option::getString("General.Version", known_library_version());
  } catch (...) {
    gmsh::finalize();
    throw;
  }
}

GmshSession::~GmshSession() { gmsh::finalize(); }

std::string GmshSession::library_version() {
  {
    std::lock_guard<std::mutex> guard(gmsh_mutex());
    if (!known_library_version().empty()) return known_library_version();
  }
  GmshSession session;
  return known_library_version();
}

std::string current_gmsh_error() {
  try {
    throw;
  } catch (const std::string& message) {
    return message;
  } catch (const char* message) {
    return message;
  } catch (const std::exception& error) {
    return error.what();
  } catch (...) {
    return "unknown Gmsh error";
  }
}

}  // namespace rouleau
