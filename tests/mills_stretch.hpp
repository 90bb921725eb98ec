#pragma once
// The optical-tweezers stretch of one red blood cell as a static solve of the solid alone
// (Mills, Qie, Dao, Lim & Suresh 2004; docs/method.md, "Static stretch"), for
// tests/test_mills_stretch.cpp (whose head says what is compared and measured) and the
// work–precision study (bench/work_precision_cells.cpp): Mills et al.'s data, the two
// membrane laws, and the solve.
#include <Eigen/Dense>
#include <Kokkos_Core.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "cells/cell_population.hpp"
#include "cells/cells_from_case.hpp"
#include "cells/static_equilibrium.hpp"
#include "cells/stretch_patches.hpp"
#include "config/cell_kinds.hpp"
#include "geometry/cell_mesh.hpp"

namespace rouleau::testing {

// ---- Mills et al. 2004

struct MillsPoint {
  double force;                                           // [pN]
  double axial, axial_lower, axial_upper;                 // [μm]
  double transverse, transverse_lower, transverse_upper;  // [μm]
};
// Digitised from Mills et al. 2004 (see the head of this file); forces as digitised.
inline const std::vector<MillsPoint> mills_2004 = {
    {0.000, 7.738, 7.160, 8.492, 7.740, 7.113, 8.355},      {15.987, 9.155, 8.344, 9.995, 6.707, 5.942, 7.451},
    {38.365, 10.905, 9.718, 12.080, 5.944, 5.093, 6.823},   {67.964, 12.322, 10.898, 13.796, 4.963, 3.874, 6.067},
    {130.513, 14.062, 12.144, 16.056, 4.529, 3.448, 5.511}, {192.688, 15.261, 12.954, 17.650, 4.257, 3.440, 5.091},
};
inline const MillsPoint& mills_point_near(double force) {
  return *std::min_element(mills_2004.begin(), mills_2004.end(), [&](const MillsPoint& a, const MillsPoint& b) {
    return std::fabs(a.force - force) < std::fabs(b.force - force);
  });
}

// ---- the cell

inline const double contact_diameter = 2.0;  // [μm], the beads' contact patch (Mills et al., Dao et al.)

inline const CellKindConfig& normal_kind() {
  static const CellKindConfig kind = builtin_cell_kinds()[0];
  return kind;
}
// The "normal" kind's mesh at a resolution preset (the paper's by default), each made once
// (Gmsh, ~0.3 s at the paper's).
inline const CellMesh& normal_mesh(MeshResolution resolution = MeshResolution::paper) {
  static std::map<MeshResolution, CellMesh> meshes;
  auto found = meshes.find(resolution);
  if (found == meshes.end()) {
    CellKindConfig kind = normal_kind();
    kind.resolution = resolution;
    found = meshes.emplace(resolution, make_cell_mesh(kind)).first;
  }
  return found->second;
}

// A membrane law: the paper's by default; the Mills membrane below.
struct Membrane {
  double shear_modulus = 4.2;           // G_s [pN/μm]
  double poisson_ratio = 0.45;
  double strain_hardening_ratio = 0.0;  // C3 / G
  double area_modulus = 0.0;            // k_A [pN/μm]
  bool volume_held = false;             // the enclosed volume held (static solve only)
};
inline const Membrane paper_membrane{};
inline const Membrane mills_membrane{5.3, 0.45, 1.0 / 30.0, 1000.0, true};

// The Mills membrane as a case file's cell kind (the head of this file), with one cell of it.
inline std::vector<std::string> mills_membrane_case_overrides() {
  char kind[256];
  std::snprintf(kind, sizeof kind,
                "cell_kinds.mills={membrane_shear_modulus_pN_um=%.17g, poisson_ratio=%.17g, "
                "strain_hardening_ratio=%.17g, area_modulus_pN_um=%.17g}",
                mills_membrane.shear_modulus, mills_membrane.poisson_ratio, mills_membrane.strain_hardening_ratio,
                mills_membrane.area_modulus);
  return {kind, "cells=[{kind=\"mills\", center_um=[20, 0, 10]}]", "time.mode=steady"};  // the cell alone: no time loop
}

// The cell with `membrane`'s law on the normal kind's mesh (as make_case_cells places it).
inline PlacedCell placed_cell(const Membrane& membrane, MeshResolution resolution = MeshResolution::paper) {
  PlacedCell cell;
  cell.mesh = &normal_mesh(resolution);
  const double g = membrane.shear_modulus / normal_kind().shell_thickness;  // G = G_s / h
  cell.material = NeoHookeanMaterial::from_moduli(g, bulk_modulus_from_poisson(g, membrane.poisson_ratio),
                                                  membrane.strain_hardening_ratio);
  cell.area_modulus = membrane.area_modulus;
  return cell;
}

// One cell with its end patches and its solver.
struct StretchSetup {
  std::unique_ptr<CellPopulation> cells;
  std::unique_ptr<StretchPatches> patches;
  std::unique_ptr<StaticEquilibrium> solver;
  explicit StretchSetup(const Membrane& membrane = paper_membrane, MeshResolution resolution = MeshResolution::paper) {
    cells = std::make_unique<CellPopulation>(std::vector<PlacedCell>{placed_cell(membrane, resolution)});
    patches = std::make_unique<StretchPatches>(*cells, 0, std::array<double, 3>{1.0, 0.0, 0.0},
                                               std::array<double, 3>{0.0, 1.0, 0.0}, contact_diameter);
    solver = std::make_unique<StaticEquilibrium>(*cells);
  }
};

struct StretchResult {
  double force = 0.0;
  StretchDiameters diameters;
  StaticEquilibriumReport report;
  double area = 0.0, reference_area = 0.0, volume = 0.0, reference_volume = 0.0;
  double distortion = 0.0;  // the largest J1 − 3
};

// The largest J1 − 3 = I1 J^(−2/3) − 3 over the cell's tetrahedra (0 unstrained; the
// hardening term raises the tangent shear modulus by a factor 1 + 30 (C3/G) (J1 − 3)²).
inline double largest_distortion(const CellPopulation& cells) {
  const auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.positions());
  const auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.reference_positions());
  const auto tets = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.element_nodes());
  double largest = 0.0;
  for (std::size_t e = 0; e < tets.extent(0); ++e) {
    Eigen::Matrix3d dm, ds;
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) {
        dm(i, k) = x0(tets(e, k + 1), i) - x0(tets(e, 0), i);
        ds(i, k) = x(tets(e, k + 1), i) - x(tets(e, 0), i);
      }
    const Eigen::Matrix3d f = ds * dm.inverse();
    largest = std::max(largest, (f.transpose() * f).trace() * std::pow(f.determinant(), -2.0 / 3.0) - 3.0);
  }
  return largest;
}

inline StretchResult stretch(double force, const Membrane& membrane = paper_membrane,
                             const StaticEquilibriumOptions& options = {},
                             MeshResolution resolution = MeshResolution::paper) {
  StretchSetup setup(membrane, resolution);
  const CellMeasures before = setup.cells->measures()[0];
  setup.solver->set_pull(setup.patches->signed_weights(), force);
  if (membrane.volume_held) setup.solver->set_volume_constraint(10.0);
  StretchResult result;
  result.force = force;
  result.report = setup.solver->solve(options);
  result.diameters = setup.patches->diameters(*setup.cells);
  const CellMeasures after = setup.cells->measures()[0];
  result.reference_area = before.area;
  result.area = after.area;
  result.reference_volume = before.volume;
  result.volume = after.volume;
  result.distortion = largest_distortion(*setup.cells);
  return result;
}

}  // namespace rouleau::testing
