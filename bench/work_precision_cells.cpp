// Work–precision of the cells (bench/work_precision.md), three families.
//
// 1. sphere_rotation, the immersed coupling: a stiff sphere in simple
// shear (tests/sphere_in_shear.hpp: filled neo-Hookean sphere, a = 2 μm, walls 16 radii
// apart, 30 steps of 1.2e-5 s), whose rotation rate has an exact reference, the free
// sphere's ω_z = −γ̇/2 (Jeffery 1922) with the two walls' correction (Goldman, Cox &
// Brenner 1967), accurate to ~0.01 % at this wall distance. Two knobs: the fluid mesh
// (n elements per side of the cube, a/h_f = n/16) and the sphere's mesh preset (coarse,
// fine). Each point is a real run; its work is the wall time of building the simulation
// (the sphere's mesh comes from the mesh cache, filled by an untimed warm-up run) and its
// 30 steps on the Kokkos threads of this run; its error |ω/ω_ref − 1|.
//
// 2. capsule_taylor, the coupling with a deforming membrane: the thin capsule of
// cases/capsule_shear (tests/capsule_in_shear.hpp) at Ca = 0.05 to t = 0.027 s, its steady
// Taylor deformation against the published D = 0.27 (Ramanujan & Pozrikidis 1998, Doddi &
// Bagchi 2008). Knob: the fluid mesh, a/h_f = 2.7 … 4.6 (n: elements across the box's x),
// at 0.9 of the explicit stable step of each mesh. (a/h_f = 5.5, the case's own, takes
// about 10 minutes: the long tier.)
//
// 3. rbc_stretch, the cell's solid alone: the optical-tweezers stretch of a red cell with
// the Mills membrane at 193 pN (tests/mills_stretch.hpp, a static solve), against Mills et
// al. 2004's mean axial diameter (15.26 μm; their error bar 12.95–17.65 μm). Knobs: the
// cell mesh preset and the solver's tolerance (the largest nodal residual over the load,
// 1e-3 … 1e-6). Work: the solve's wall time (the mesh made beforehand); error
// |D_axial / D_Mills − 1| (n in the CSV: −log10 of the tolerance). The model, not the
// resolution, sets this error's floor (9–10 %, inside their bar): the paper and fine meshes
// agree to 0.1 %, and the coarse one is 1 % short of them.
//
//   work_precision_cells [--out FILE.csv] [--sizes 8,16,24,32]
#include <Kokkos_Core.hpp>
#include <array>
#include <cmath>
#include <cstdio>
#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "capsule_in_shear.hpp"
#include "config/derived.hpp"
#include "mills_stretch.hpp"
#include "sphere_in_shear.hpp"

int main(int argc, char* argv[]) {
  Kokkos::ScopeGuard kokkos(argc, argv);
  std::string out = "work_precision_cells.csv";
  std::vector<int> sizes{8, 16, 24, 32};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--out" && i + 1 < argc) {
      out = argv[++i];
    } else if (arg == "--sizes" && i + 1 < argc) {
      sizes.clear();
      std::stringstream list(argv[++i]);
      std::string item;
      while (std::getline(list, item, ',')) sizes.push_back(std::stoi(item));
    } else {
      std::cerr << "work_precision_cells: unknown argument '" << arg << "' (--out FILE, --sizes 8,16)\n";
      return 2;
    }
  }
  const auto folder = std::filesystem::temp_directory_path() / ("rouleau_work_precision_cells_" + std::to_string(getpid()));
  std::filesystem::create_directories(folder);
  const double walls_apart = 16.0;
  const int threads = Kokkos::DefaultExecutionSpace().concurrency();
  std::ofstream csv(out + ".part");
  // value and reference: ω_z and ω_ref [1/s] for the sphere, D and the published D for the
  // capsule, D_axial and Mills' [μm] for the stretch.
  csv << "family,mesh_preset,n,a_over_h,value,reference,error,seconds,threads\n";
  for (const char* preset : {"coarse", "fine"}) {
    rouleau::testing::run_sphere_in_shear(walls_apart, 4, folder.string(), preset);  // warm-up: the mesh cache
    for (int n : sizes) {
      Kokkos::fence();
      Kokkos::Timer timer;
      const auto r = rouleau::testing::run_sphere_in_shear(walls_apart, n, folder.string(), preset);
      Kokkos::fence();
      const double seconds = timer.seconds();
      csv << "sphere_rotation," << preset << ',' << n << ',' << r.a_over_h << ',' << r.omega << ',' << r.expected << ','
          << r.error << ',' << seconds << ',' << threads << '\n';
      std::printf("sphere rotation, %s sphere, n = %2d (a/h_f %.2f): error %.3e in %.2f s\n", preset, n, r.a_over_h,
                  r.error, seconds);
      std::fflush(stdout);
    }
  }
  std::filesystem::remove_all(folder);
  const std::string capsule_case = std::string(ROULEAU_SOURCE_DIR) + "/cases/capsule_shear/case.toml";
  for (const auto& elements : {std::array<int, 3>{18, 23, 18}, std::array<int, 3>{24, 30, 24},
                               std::array<int, 3>{30, 38, 30}}) {
    const std::string mesh = "domain.elements=[" + std::to_string(elements[0]) + "," + std::to_string(elements[1]) +
                             "," + std::to_string(elements[2]) + "]";
    const double stable = rouleau::derive_quantities(rouleau::load_case(capsule_case, {mesh})).stable_dt;
    char step[64];
    std::snprintf(step, sizeof step, "time.dt_s=%.6g", 0.9 * stable);
    Kokkos::fence();
    Kokkos::Timer timer;
    const auto r = rouleau::testing::run_capsule(0.05, {mesh, step, "time.end_s=0.027"});
    Kokkos::fence();
    const double seconds = timer.seconds();
    const double published = 0.27;
    csv << "capsule_taylor,default," << elements[0] << ',' << r.a_over_h << ',' << r.deformation << ',' << published
        << ',' << std::fabs(r.deformation / published - 1.0) << ',' << seconds << ',' << threads << '\n';
    std::printf("capsule Taylor deformation at Ca = 0.05, a/h_f %.2f: D = %.4f (published %.2f), error %.3e in %.1f s\n",
                r.a_over_h, r.deformation, published, std::fabs(r.deformation / published - 1.0), seconds);
    std::fflush(stdout);
  }
  const double force = 192.688;  // [pN], Mills et al.'s largest
  const rouleau::testing::MillsPoint& mills = rouleau::testing::mills_point_near(force);
  for (const auto& [preset, resolution] : {std::pair{"coarse", rouleau::MeshResolution::coarse},
                                           std::pair{"paper", rouleau::MeshResolution::paper},
                                           std::pair{"fine", rouleau::MeshResolution::fine}}) {
    rouleau::testing::normal_mesh(resolution);  // made before the clock starts
    for (const int digits : {3, 4, 5, 6}) {
      rouleau::StaticEquilibriumOptions options;
      options.relative_tolerance = std::pow(10.0, -digits);
      Kokkos::fence();
      Kokkos::Timer timer;
      const auto r = rouleau::testing::stretch(force, rouleau::testing::mills_membrane, options, resolution);
      Kokkos::fence();
      const double seconds = timer.seconds();
      const double error = std::fabs(r.diameters.axial / mills.axial - 1.0);
      csv << "rbc_stretch," << preset << ',' << digits << ",," << r.diameters.axial << ',' << mills.axial << ','
          << error << ',' << seconds << ',' << threads << '\n';
      std::printf("RBC stretch at %.0f pN, %s mesh, tolerance 1e-%d: axial %.4f um (Mills %.3f), error %.3e in %.2f s%s\n",
                  force, preset, digits, r.diameters.axial, mills.axial, error, seconds,
                  r.report.converged ? "" : "  NOT CONVERGED");
      std::fflush(stdout);
    }
  }
  csv.close();
  if (std::rename((out + ".part").c_str(), out.c_str()) != 0) {
    std::cerr << "work_precision_cells: cannot rename " << out << ".part to " << out << "\n";
    return 1;
  }
  std::printf("wrote %s (%d threads)\n", out.c_str(), threads);
  return 0;
}
