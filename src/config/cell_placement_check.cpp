#include "config/cell_placement_check.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "util/number_text.hpp"
#include "geometry/box_overlaps.hpp"
#include "geometry/cell_shapes.hpp"
#include "util/errors.hpp"
#include "util/constants.hpp"

namespace rouleau {
namespace {
using Vector3 = std::array<double, 3>;
using Matrix3 = std::array<std::array<double, 3>, 3>;

Vector3 multiply(const Matrix3& m, const Vector3& v) {
  return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
          m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}
Vector3 multiply_transposed(const Matrix3& m, const Vector3& v) {
  return {m[0][0] * v[0] + m[1][0] * v[1] + m[2][0] * v[2], m[0][1] * v[0] + m[1][1] * v[1] + m[2][1] * v[2],
          m[0][2] * v[0] + m[1][2] * v[1] + m[2][2] * v[2]};
}

// A length or position [μm] in a message of this check: 4 significant digits.
std::string format_length(double value) { return format_number(value, 4); }
std::string format_point(const Vector3& p) {
  return "[" + format_length(p[0]) + ", " + format_length(p[1]) + ", " + format_length(p[2]) + "]";
}

// A cell in a vessel: every placed sample inside the lumen (0 ≤ x ≤ L, r < R(x)); and, unless
// vessel.allow_squeeze, no wider than the throat: its passing diameter (the middle extent
// of its body-frame bounding box: a disc's or a sphere's diameter, a sickle's width; a
// rigid body whose passing diameter exceeds a round opening cannot pass it) at most 2 R_t.
void check_inside_vessel(const CaseConfig& config, std::size_t i, const std::vector<Vector3>& samples,
                         const Matrix3& rotation) {
  const std::string& file = config.source_file;
  const CellPlacement& cell = config.cells[i];
  const VesselProfile& profile = config.vessel.profile;
  const std::string key = "cells[" + std::to_string(i) + "].";
  const std::string which = "cell " + std::to_string(i) + " (" + cell.kind + ")";
  Vector3 lowest{+INFINITY, +INFINITY, +INFINITY}, highest{-INFINITY, -INFINITY, -INFINITY};
  for (const Vector3& p : samples) {
    for (int axis = 0; axis < 3; ++axis) {
      lowest[axis] = std::min(lowest[axis], p[axis]);
      highest[axis] = std::max(highest[axis], p[axis]);
    }
    const Vector3 rotated = multiply(rotation, p);
    const Vector3 x{cell.center[0] + rotated[0], cell.center[1] + rotated[1], cell.center[2] + rotated[2]};
    const double r = std::hypot(x[1], x[2]);
    if (x[0] < 0.0 || x[0] > vessel_length(profile))
      throw InputError(file, key + "center_um",
                       which + " reaches beyond the vessel's ends: its surface point " + format_point(x) +
                           " μm is outside x in [0, " + format_length(vessel_length(profile)) + "] μm");
    if (!(r < vessel_radius(profile, x[0])))
      throw InputError(file, key + "center_um",
                       which + " reaches outside the vessel: its surface point " + format_point(x) +
                           " μm is at distance " + format_length(r) + " μm from the axis where the lumen's radius is " +
                           format_length(vessel_radius(profile, x[0])) + " μm");
  }
  Vector3 extent{highest[0] - lowest[0], highest[1] - lowest[1], highest[2] - lowest[2]};
  std::sort(extent.begin(), extent.end());
  const double passing_diameter = extent[1];
  if (!config.vessel.allow_squeeze && passing_diameter > 2.0 * profile.throat_radius)
    throw InputError(file, key + "kind",
                     which + " is larger than the vessel: its passing diameter " + format_length(passing_diameter) +
                         " μm exceeds the throat's diameter " + format_length(2.0 * profile.throat_radius) +
                         " μm; set vessel.allow_squeeze = true to let the flow squeeze it through");
}
}  // namespace

void check_cell_placement(const CaseConfig& config) {
  // Surface samples this far apart: two cells 0.3 μm apart are told from touching ones,
  // and the surface between samples bulges by less than spacing²/(8 × curvature radius).
  const double sample_spacing = 0.15;
  const std::string& file = config.source_file;
  const auto cell_key = [](std::size_t i, const char* field) {
    return "cells[" + std::to_string(i) + "]." + field;
  };

  // Each cell's kind; each kind's samples once (body frame) and its bounding radius.
  struct KindSamples {
    std::vector<Vector3> samples;
    double bounding_radius = 0.0;
  };
  std::map<std::size_t, KindSamples> samples_of_kind;
  std::vector<std::size_t> kind_of_cell(config.cells.size());
  for (std::size_t i = 0; i < config.cells.size(); ++i) {
    const auto& name = config.cells[i].kind;
    const auto found = std::find_if(config.cell_kinds.begin(), config.cell_kinds.end(),
                                    [&](const CellGeometry& kind) { return kind.name == name; });
    if (found == config.cell_kinds.end()) {
      std::string known;
      for (const auto& kind : config.cell_kinds) known += (known.empty() ? "\"" : ", \"") + kind.name + "\"";
      throw InputError(file, cell_key(i, "kind"),
                       "unknown cell kind \"" + name + "\"; the kinds are " + (known.empty() ? "(none)" : known));
    }
    kind_of_cell[i] = static_cast<std::size_t>(found - config.cell_kinds.begin());
    if (samples_of_kind.count(kind_of_cell[i])) continue;
    KindSamples entry;
    try {
      entry.samples = cell_surface_samples(*found, sample_spacing);
    } catch (const std::runtime_error& error) {
      throw InputError(file, "cell_kinds." + found->name, error.what());
    }
    for (const auto& p : entry.samples)
      entry.bounding_radius = std::max(entry.bounding_radius, std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
    entry.bounding_radius += sample_spacing;  // the surface between samples
    samples_of_kind.emplace(kind_of_cell[i], std::move(entry));
  }

  // Inside the domain: every sample, placed, within [lower, upper] along each axis.
  std::vector<Matrix3> rotation(config.cells.size());
  for (std::size_t i = 0; i < config.cells.size(); ++i) {
    const auto& cell = config.cells[i];
    rotation[i] = placement_rotation(cell.orientation);
    Vector3 lowest{+INFINITY, +INFINITY, +INFINITY}, highest{-INFINITY, -INFINITY, -INFINITY};
    for (const auto& p : samples_of_kind.at(kind_of_cell[i]).samples) {
      const Vector3 rotated = multiply(rotation[i], p);
      for (int axis = 0; axis < 3; ++axis) {
        lowest[axis] = std::min(lowest[axis], cell.center[axis] + rotated[axis]);
        highest[axis] = std::max(highest[axis], cell.center[axis] + rotated[axis]);
      }
    }
    if (config.vessel.enabled) {
      check_inside_vessel(config, i, samples_of_kind.at(kind_of_cell[i]).samples, rotation[i]);
      continue;
    }
    for (int axis = 0; axis < 3; ++axis) {
      const double lower = config.domain.lower[axis], upper = config.domain.upper[axis];
      if (lowest[axis] < lower || highest[axis] > upper)
        throw InputError(file, cell_key(i, "center_um"),
                         "cell " + std::to_string(i) + " (" + cell.kind + ") reaches outside the fluid domain: its surface spans [" +
                             format_length(lowest[axis]) + ", " + format_length(highest[axis]) + "] μm along " +
                             axis_names[axis] + ", the domain [" + format_length(lower) + ", " + format_length(upper) +
                             "] μm");
    }
  }

  // Overlaps: only pairs whose bounding spheres meet (their boxes first,
  // geometry/box_overlaps.hpp); then no sample of either inside the other.
  std::vector<Box> boxes(config.cells.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const double radius = samples_of_kind.at(kind_of_cell[i]).bounding_radius;
    for (int axis = 0; axis < 3; ++axis) {
      boxes[i][axis] = config.cells[i].center[axis] - radius;
      boxes[i][3 + axis] = config.cells[i].center[axis] + radius;
    }
  }
  std::vector<std::pair<std::size_t, std::size_t>> near_pairs;  // (later cell j, earlier cell i)
  for (const auto& [i, j] : boxes_within(boxes, 0.0)) {
    const double radius_i = samples_of_kind.at(kind_of_cell[i]).bounding_radius;
    const double radius_j = samples_of_kind.at(kind_of_cell[j]).bounding_radius;
    double distance_squared = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
      const double d = config.cells[j].center[axis] - config.cells[i].center[axis];
      distance_squared += d * d;
    }
    if (distance_squared < (radius_i + radius_j) * (radius_i + radius_j)) near_pairs.emplace_back(j, i);
  }
  std::sort(near_pairs.begin(), near_pairs.end());  // report the first pair in file order
  const auto any_sample_inside = [&](std::size_t from, std::size_t into) {
    const auto& into_kind = config.cell_kinds[kind_of_cell[into]];
    for (const auto& p : samples_of_kind.at(kind_of_cell[from]).samples) {
      const Vector3 rotated = multiply(rotation[from], p);
      Vector3 relative;
      for (int axis = 0; axis < 3; ++axis)
        relative[axis] = config.cells[from].center[axis] + rotated[axis] - config.cells[into].center[axis];
      if (inside_cell(into_kind, multiply_transposed(rotation[into], relative))) return true;
    }
    return false;
  };
  for (const auto& [j, i] : near_pairs) {
    if (any_sample_inside(j, i) || any_sample_inside(i, j))
      throw InputError(file, cell_key(j, "center_um"),
                       "cell " + std::to_string(j) + " (" + config.cells[j].kind + ") overlaps cells[" + std::to_string(i) +
                           "] (" + config.cells[i].kind + " at " + format_point(config.cells[i].center) + " μm)");
  }
}


}  // namespace rouleau
