#pragma once
// The geometry of a kind of cell: its shape, what of it is solid, its sizes and its mesh
// resolution, all the shape functions (cell_shapes.hpp) and the mesher (cell_mesh.hpp)
// need. A case's cell kind (config/case_config.hpp, CellKindConfig) adds the material.
// Host-only: includes no Kokkos header.
#include <array>
#include <string>

#include "geometry/named_choice.hpp"

namespace rouleau {

// The body shapes cells are meshed from.
enum class CellShape {
  rbc,     // Evans–Fung biconcave disc, paper eq. (1), revolved about its axis (local z)
  sickle,  // crescent: an ellipsoid bent along a circular arc in its local x–y plane
  sphere,  // sphere / spherical capsule
  spheroid,  // ellipsoid of revolution about its local z axis: oblate (flat) or prolate (long)
};
// What of the body is solid: its whole volume, or a membrane layer of given thickness
// enclosing fluid that belongs to the Eulerian mesh.
enum class CellBody { shell, filled };
// Mesh resolution presets (element sizes per shape: cell_element_size(), cell_mesh.hpp).
enum class MeshResolution { coarse, paper, fine };

// The case-file spelling of each choice, in the order messages list them.
inline constexpr std::array<NamedChoice<CellShape>, 4> cell_shape_names{{{CellShape::rbc, "rbc"},
                                                                         {CellShape::sickle, "sickle"},
                                                                         {CellShape::sphere, "sphere"},
                                                                         {CellShape::spheroid, "spheroid"}}};
inline constexpr std::array<NamedChoice<CellBody>, 2> cell_body_names{
    {{CellBody::shell, "shell"}, {CellBody::filled, "filled"}}};
inline constexpr std::array<NamedChoice<MeshResolution>, 3> mesh_resolution_names{
    {{MeshResolution::coarse, "coarse"}, {MeshResolution::paper, "paper"}, {MeshResolution::fine, "fine"}}};

// Defaults: the normal RBC's geometry (a hollow Evans–Fung disc of 7.82 μm).
struct CellGeometry {
  std::string name;                  // the kind's name, which errors about its shape quote
  CellShape shape = CellShape::rbc;  // key shape = "rbc" | "sickle" | "sphere" | "spheroid"
  CellBody body = CellBody::shell;   // key body = "shell" | "filled"
  // rbc, sphere: the diameter; spheroid: the equatorial diameter 2a [μm]   key diameter_um
  double diameter = 7.82;
  // spheroid: the polar semi-axis over the equatorial one, c/a (< 1 oblate, > 1 prolate)
  double axis_ratio = 1.0;    // key axis_ratio
  // sickle: centre-line length, in-plane width, out-of-plane thickness of the unbent
  // ellipsoid, and the radius of the arc its centre line is bent along [μm]
  double length = 14.0;       // key length_um
  double width = 4.2;         // key width_um
  double thickness = 3.0;     // key thickness_um
  double arc_radius = 8.0;    // key arc_radius_um
  double shell_thickness = 0.36;  // shell body: membrane thickness [μm]   key shell_thickness_um
  MeshResolution resolution = MeshResolution::paper;  // key resolution
  double mesh_size = 0.0;     // element size [μm] overriding the preset when > 0   key mesh_size_um
};

}  // namespace rouleau
