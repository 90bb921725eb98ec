// The `rouleau` command: it validates the case first, then starts Kokkos (only for `run`
// and `info`, run/kokkos_session.hpp) and calls the library.
#include <iostream>
#include <string>

#include "cli/cli.hpp"
#include "cli/host_info.hpp"
#include "config/derived.hpp"
#include "config/load_case.hpp"
#include "parallel/mpi_session.hpp"
#include "run/kokkos_runtime_info.hpp"
#include "run/kokkos_session.hpp"
#include "run/run_case.hpp"
#include "util/errors.hpp"

namespace {

int run_command(const rouleau::CommandLine& command_line) {
  // The whole case is validated before Kokkos starts: bad input costs no start-up.
  rouleau::RunOptions options = rouleau::run_options(command_line);
  const rouleau::CaseConfig config = rouleau::load_run_case(command_line, options.restart, std::cerr);
  rouleau::derive_quantities(config);
  rouleau::check_memory(config, command_line);  // a case that does not fit stops here
  // MPI before Kokkos: under `mpirun -np N` the fluid is split across N ranks.
  rouleau::MpiSession mpi;
  rouleau::KokkosSession kokkos("rouleau", command_line.threads);
  return rouleau::run_case(config, options);
}

int info_command(const rouleau::CommandLine& command_line) {
  rouleau::KokkosSession kokkos("rouleau", command_line.threads);
  auto lines = rouleau::host_dependency_versions();
  for (auto& line : rouleau::kokkos_runtime_info()) lines.push_back(std::move(line));
  std::cout << rouleau::format_info_lines(lines);
  return static_cast<int>(rouleau::ExitCode::done);
}

}  // namespace

int main(int argc, char** argv) {
  const rouleau::CommandLine command_line = rouleau::parse_command_line(argc, argv, std::cout, std::cerr);
  return rouleau::run_reporting_errors(
      [&] {
        switch (command_line.command) {
          case rouleau::Command::check: return rouleau::check_case(command_line, std::cout);
          case rouleau::Command::run: return run_command(command_line);
          case rouleau::Command::info: return info_command(command_line);
          case rouleau::Command::finished: break;
        }
        return command_line.exit_code;
      },
      std::cerr);
}
