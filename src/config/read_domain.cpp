// The readers of the fluid domain: a [domain] box with its [boundary.SIDE] tables, or a
// [vessel] with [boundary.inlet], [boundary.outlet] and [boundary.wall].
#include <algorithm>

#include "config/case_section_readers.hpp"
#include "util/number_text.hpp"
#include "util/constants.hpp"

namespace rouleau {
namespace {

// The keys a side of each boundary type takes (besides "type").
std::vector<std::string_view> boundary_keys_of(BoundaryType type) {
  switch (type) {
    case BoundaryType::periodic: return {};
    case BoundaryType::wall: return {"velocity_um_s"};
    case BoundaryType::inflow: return {"mean_speed_um_s", "profile"};
    case BoundaryType::traction: return {"pressure_Pa", "parallel_flow"};
  }
  return {};
}

// The keys of a boundary of a known type, a box side's or a vessel end's: each given key
// must belong to the type; an inflow needs its mean speed.
void read_boundary_of_type(const TableReader& reader, BoundaryConfig& boundary) {
  const std::vector<std::string_view> allowed = boundary_keys_of(boundary.type);
  for (const std::string& key : reader.present_keys()) {
    if (key == "type" || std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    reader.fail(key, "does not belong to boundary type \"" + std::string(toml_name(boundary.type)) + "\" (it takes " +
                         (allowed.empty() ? std::string("no key besides type") : joined(allowed, false)) + ")");
  }
  const auto mean_speed = reader.number("mean_speed_um_s");
  if (boundary.type == BoundaryType::inflow) require(reader, "mean_speed_um_s", mean_speed);
  assign(boundary.mean_speed, mean_speed);
  assign(boundary.profile, reader.choice<InflowProfile>("profile"));
  assign(boundary.pressure, reader.number("pressure_Pa"));
  assign(boundary.parallel_flow, reader.boolean("parallel_flow"));
}

}  // namespace

void read_domain(const TableReader& root, DomainConfig& domain) {
  const TableReader section = root.table("domain");
  domain.lower = require(section, "lower_um", section.number3("lower_um"));
  domain.upper = require(section, "upper_um", section.number3("upper_um"));
  for (std::size_t axis = 0; axis < 3; ++axis)
    if (!(domain.upper[axis] > domain.lower[axis]))
      section.fail("upper_um", "component " + std::string(axis_names[axis]) + ": must be > lower_um's " +
                                   format_number(domain.lower[axis]) + ", got " + format_number(domain.upper[axis]));
  const auto elements = section.integer3("elements");
  require(section, "elements", elements);
  assign(domain.elements, elements);
  assign(domain.wall_grading, section.number3("wall_grading"));
}

void read_boundaries(const TableReader& root, DomainConfig& domain) {
  const TableReader boundaries =
      root.table_of_tables("boundary", std::vector<std::string_view>(side_names.begin(), side_names.end()));
  for (int side = 0; side < 6; ++side) {
    const TableReader reader = boundaries.table(side_names[side], "boundary.SIDE");
    BoundaryConfig& boundary = domain.boundary[side];
    assign(boundary.type, reader.choice<BoundaryType>("type"));
    read_boundary_of_type(reader, boundary);
    const int axis = side / 2;
    assign(boundary.velocity, reader.number3("velocity_um_s"));
    if (boundary.velocity[axis] != 0.0)
      reader.fail("velocity_um_s", "component " + std::string(axis_names[axis]) +
                                       ": must be 0 (a wall does not move through itself; use type = \"inflow\"), got " +
                                       format_number(boundary.velocity[axis]));
  }
  for (int axis = 0; axis < 3; ++axis) {
    const int low = 2 * axis, high = 2 * axis + 1;
    const bool low_periodic = domain.boundary[low].type == BoundaryType::periodic;
    const bool high_periodic = domain.boundary[high].type == BoundaryType::periodic;
    if (low_periodic != high_periodic) {
      const int lonely = low_periodic ? high : low, partner = low_periodic ? low : high;
      boundaries.fail(std::string(side_names[lonely]) + ".type", std::string("must be \"periodic\" because boundary.") + side_names[partner] +
                                      " is periodic (periodic sides come in pairs)");
    }
    if (low_periodic && domain.elements[axis] < 2)
      root.fail("domain.elements", std::string("component ") + axis_names[axis] +
                                       ": must be ≥ 2 along a periodic direction, got " +
                                       std::to_string(domain.elements[axis]));
  }
}

void read_vessel(const TableReader& root, VesselConfig& vessel) {
  const TableReader section = root.table("vessel");
  vessel.enabled = true;
  VesselProfile& p = vessel.profile;
  p.radius = require(section, "radius_um", section.number("radius_um"));
  p.throat_radius = section.number("throat_radius_um").value_or(p.radius);
  p.inlet_length = require(section, "inlet_length_um", section.number("inlet_length_um"));
  p.contraction_length = section.number("contraction_length_um").value_or(0.0);
  p.throat_length = section.number("throat_length_um").value_or(0.0);
  p.diffuser_length = section.number("diffuser_length_um").value_or(0.0);
  p.outlet_length = section.number("outlet_length_um").value_or(0.0);
  assign(p.transition, section.choice<VesselTransition>("transition"));
  if (const auto problem = vessel_profile_problem(p)) section.fail(problem->key, problem->reason);
  vessel.sizes.element_size = require(section, "element_size_um", section.number("element_size_um"));
  vessel.sizes.wall_element_size = section.number("wall_element_size_um").value_or(0.0);
  assign(vessel.sizes.refined_scale, section.number("refined_element_scale"));
  assign(vessel.sizes.refined_from, section.number("refined_from_um"));
  assign(vessel.sizes.refined_to, section.number("refined_to_um"));
  if (const auto problem = vessel_mesh_sizes_problem(p, vessel.sizes)) section.fail(problem->key, problem->reason);
  assign(vessel.allow_squeeze, section.boolean("allow_squeeze"));
  assign(vessel.wall_repulsion_pressure, section.number("wall_repulsion_Pa"));
  assign(vessel.wall_repulsion_range, section.number("wall_repulsion_range_um"));
  if (!(vessel.wall_repulsion_range < p.throat_radius))
    section.fail("wall_repulsion_range_um", "must be below the throat's radius " + format_number(p.throat_radius) +
                                                " μm (it is a short-range force)");
}

// [boundary.inlet] (inflow or traction), [boundary.outlet] (traction), [boundary.wall]
// (type "wall" only: the vessel's wall does not move).
void read_vessel_boundaries(const TableReader& root, VesselConfig& vessel) {
  const TableReader boundaries = root.table_of_tables("boundary", {"inlet", "outlet", "wall"});
  // An end of the vessel; the outlet takes only a traction.
  const auto read_end = [&](const char* name, BoundaryConfig& boundary, bool traction_only) {
    if (!boundaries.has(name))
      boundaries.fail(name, std::string("missing: a vessel needs [boundary.") + name + "] (type = " +
                                (traction_only ? "\"traction\"" : "\"inflow\" or \"traction\"") + ")");
    const TableReader reader = boundaries.table(name, "boundary.END");
    const std::vector<std::string_view> types = traction_only ? spellings({BoundaryType::traction})
                                                              : std::vector<std::string_view>{};
    boundary.type = require(reader, "type", reader.choice<BoundaryType>("type", types));
    read_boundary_of_type(reader, boundary);
  };
  read_end("inlet", vessel.inlet, false);
  read_end("outlet", vessel.outlet, true);
  const TableReader wall = boundaries.table("wall", "boundary.wall");
  (void)wall.choice<BoundaryType>("type");
}

}  // namespace rouleau
