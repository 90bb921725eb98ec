#include "fluid/flow_rates.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

#include "geometry/triangle_area.hpp"

namespace rouleau {
namespace {

using Point = std::array<double, 3>;

Point position(const Kokkos::View<double* [3]>::HostMirror& x, int node) { return {x(node, 0), x(node, 1), x(node, 2)}; }

}  // namespace

BoundaryIntegrals::BoundaryIntegrals(const FluidMesh& mesh) : mesh_(mesh) {
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  for (const BoundaryFaces& b : mesh.boundaries) {
    std::vector<double>& areas = face_areas_[b.name];
    for (const auto& face : b.faces) {
      const bool triangle = face[3] == face[2];
      double a = triangle_area(position(x, face[0]), position(x, face[1]), position(x, face[2]));
      if (!triangle) a += triangle_area(position(x, face[0]), position(x, face[2]), position(x, face[3]));
      areas.push_back(a);
    }
  }
}

const std::vector<double>& BoundaryIntegrals::face_areas(const std::string& name) const {
  const auto found = face_areas_.find(name);
  if (found == face_areas_.end())
    throw std::out_of_range("rouleau::BoundaryIntegrals: no boundary named '" + name + "'");
  return found->second;
}

template <class Field>
double BoundaryIntegrals::integral(const std::string& name, const Field& f) const {
  const BoundaryFaces& b = mesh_.boundary(name);
  const std::vector<double>& areas = face_areas(name);
  double sum = 0.0;
  for (std::size_t k = 0; k < b.faces.size(); ++k) {
    const auto& face = b.faces[k];
    const int corners = face[3] == face[2] ? 3 : 4;
    double corner_sum = 0.0;
    for (int c = 0; c < corners; ++c) corner_sum += f(face[c]);
    sum += areas[k] * corner_sum / corners;
  }
  return sum;
}

double BoundaryIntegrals::area(const std::string& name) const {
  double sum = 0.0;
  for (double a : face_areas(name)) sum += a;
  return sum;
}

double BoundaryIntegrals::flow_rate(const std::vector<double>& velocity, const std::string& name) const {
  const BoundaryFaces& b = mesh_.boundary(name);
  if (b.outward_normal[0] == 0.0 && b.outward_normal[1] == 0.0 && b.outward_normal[2] == 0.0)
    throw std::invalid_argument("rouleau::BoundaryIntegrals::flow_rate: boundary '" + name + "' is not planar");
  return integral(name, [&](int node) {
    return velocity[3 * node] * b.outward_normal[0] + velocity[3 * node + 1] * b.outward_normal[1] +
           velocity[3 * node + 2] * b.outward_normal[2];
  });
}

double BoundaryIntegrals::mean_pressure(const std::vector<double>& pressure, const std::string& name) const {
  return integral(name, [&](int node) { return pressure[node]; }) / area(name);
}

double cross_section_flow_rate(const FluidMesh& mesh, const std::vector<double>& velocity, int axis,
                               double position_on_axis) {
  if (mesh.element_type != FluidElementType::tetrahedron4)
    throw std::invalid_argument("rouleau::cross_section_flow_rate: needs a tetrahedral mesh");
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  auto elements = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.element_nodes);
  double flow = 0.0;
  for (int e = 0; e < mesh.num_elements; ++e) {
    // Where the plane cuts the edges: points and the interpolated velocity component.
    double s[4];
    for (int a = 0; a < 4; ++a) s[a] = x(elements(e, a), axis) - position_on_axis;
    Point cut[4];
    double value[4];
    int count = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) {
        if ((s[a] < 0.0) == (s[b] < 0.0)) continue;
        const double t = s[a] / (s[a] - s[b]);
        const int na = elements(e, a), nb = elements(e, b);
        for (int d = 0; d < 3; ++d) cut[count][d] = x(na, d) + t * (x(nb, d) - x(na, d));
        value[count] = velocity[3 * na + axis] + t * (velocity[3 * nb + axis] - velocity[3 * na + axis]);
        ++count;
      }
    if (count == 3) {
      flow += triangle_area(cut[0], cut[1], cut[2]) * (value[0] + value[1] + value[2]) / 3.0;
    } else if (count == 4) {
      // For the split {a, b} | {c, d} (a < b) the loop above cuts a–c, a–d, b–c, b–d in
      // this order; around the quadrilateral they come as a–c, a–d, b–d, b–c.
      const int cycle[4] = {0, 1, 3, 2};
      const Point &p0 = cut[cycle[0]], &p1 = cut[cycle[1]], &p2 = cut[cycle[2]], &p3 = cut[cycle[3]];
      const double v0 = value[cycle[0]], v1 = value[cycle[1]], v2 = value[cycle[2]], v3 = value[cycle[3]];
      flow += triangle_area(p0, p1, p2) * (v0 + v1 + v2) / 3.0 + triangle_area(p0, p2, p3) * (v0 + v2 + v3) / 3.0;
    }
  }
  return flow;
}

}  // namespace rouleau
