// The exact cell shapes: the Evans–Fung RBC, the sphere and spheroid and the sickle crescent, their
// volumes and areas by quadrature, inside tests, surface samples and placement rotations.
//
// Sickle construction (cited by the README). Start from the ellipsoid
//   (x/a)² + (y/b)² + (z/c)² ≤ 1,  a = length/2, b = width/2, c = thickness/2,
// with its long axis along x, and bend it along a circular arc of radius ρ = arc_radius in
// the x–y plane with the map
//   B(x, y, z) = ((ρ + y) sin(x/ρ), (ρ + y) cos(x/ρ) − ρ, z):
// the centre line y = z = 0 goes onto the circle of radius ρ about (0, −ρ, 0), a point at
// signed distance y from the centre line goes onto the circle of radius ρ + y, and the
// plane cross-section at x goes rigidly onto the radial plane at angle x/ρ. Hence the
// bent body's cross-sections in the radial planes are exactly the ellipses of the unbent
// one, and the arc length along the centre line is x. The Jacobian of B is
// det ∂B/∂(x, y, z) = (ρ + y)/ρ = 1 + y/ρ, so
//   V_bent = ∫_E (1 + y/ρ) dV = V_E + (1/ρ) ∫_E y dV = V_E = (4/3)π a b c,
// because the ellipsoid is symmetric in y: the bend keeps the volume exactly (the outer
// half grows by as much as the inner half shrinks). B is one-to-one and orientation-
// preserving on the body when ρ > b (the inner side stays on the arc-centre's far side)
// and a < πρ (the two tips do not meet around the circle). Finally the body is shifted
// along y by −Ȳ so that the centroid of the volume it encloses is at the origin (x̄ = 0
// by the x → −x symmetry). In the body frame the convex side faces +y and the tips point
// toward −y. The shell body's inner surface is the ellipsoid with semi-axes a − h, b − h,
// c − h bent by the same map and shifted by the same Ȳ: an approximation of the true
// inward offset by h (exact on the centre line's cross-section at x = 0 along y and z,
// thinner than h near the tips).
#include "geometry/cell_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "geometry/cell_shape_details.hpp"
#include "util/number_text.hpp"
#include "util/constants.hpp"

namespace rouleau {

namespace geometry_detail {

namespace {
// Evans–Fung coefficients (paper eq. 1, with the sign of a2 corrected).
constexpr double evans_fung_a0 = 0.207;
constexpr double evans_fung_a1 = 2.002;
constexpr double evans_fung_a2 = -1.122;

std::string format_length(double value) { return format_number(value, 4) + " μm"; }

[[noreturn]] void fail(const CellGeometry& kind, const std::string& reason) {
  throw std::runtime_error(describe_kind(kind) + ": " + reason);
}

void require_positive(const CellGeometry& kind, double value, const char* what) {
  if (!(std::isfinite(value) && value > 0.0))
    fail(kind, std::string(what) + " must be a positive number of μm, not " + std::to_string(value));
}

// Whether the open segments p0–p1 and q0–q1 cross (proper intersection or touching).
double orientation(const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}
bool segments_meet(const std::array<double, 2>& p0, const std::array<double, 2>& p1,
                   const std::array<double, 2>& q0, const std::array<double, 2>& q1) {
  const double d1 = orientation(q0, q1, p0), d2 = orientation(q0, q1, p1);
  const double d3 = orientation(p0, p1, q0), d4 = orientation(p0, p1, q1);
  return ((d1 > 0) != (d2 > 0) || d1 == 0 || d2 == 0) && ((d3 > 0) != (d4 > 0) || d3 == 0 || d4 == 0) &&
         std::min(p0[0], p1[0]) <= std::max(q0[0], q1[0]) && std::min(q0[0], q1[0]) <= std::max(p0[0], p1[0]) &&
         std::min(p0[1], p1[1]) <= std::max(q0[1], q1[1]) && std::min(q0[1], q1[1]) <= std::max(p0[1], p1[1]);
}
}  // namespace

std::string describe_kind(const CellGeometry& kind) {
  return "cell kind \"" + kind.name + "\" (" + name_of(cell_shape_names, kind.shape) + " " +
         name_of(cell_body_names, kind.body) + ")";
}

QuadratureRule gauss_legendre(int n) {
  // Nodes are the roots of the Legendre polynomial P_n, found by Newton's method from
  // the estimate cos(π(i − ¼)/(n + ½)); weights w = 2 / ((1 − x²) P_n'(x)²). P_n and
  // P_n' from the three-term recurrence k P_k = (2k − 1) x P_{k−1} − (k − 1) P_{k−2}
  // and P_n' = n (x P_n − P_{n−1}) / (x² − 1).
  QuadratureRule rule;
  rule.nodes.resize(n);
  rule.weights.resize(n);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double x = std::cos(pi * (i + 0.75) / (n + 0.5));
    double derivative = 0.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p_previous = 1.0, p = x;
      for (int k = 2; k <= n; ++k) {
        const double p_next = ((2.0 * k - 1.0) * x * p - (k - 1.0) * p_previous) / k;
        p_previous = p;
        p = p_next;
      }
      derivative = n * (x * p - p_previous) / (x * x - 1.0);
      const double step = p / derivative;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    const double weight = 2.0 / ((1.0 - x * x) * derivative * derivative);
    rule.nodes[i] = -x;
    rule.nodes[n - 1 - i] = x;
    rule.weights[i] = rule.weights[n - 1 - i] = weight;
  }
  return rule;
}

std::array<double, 2> rbc_profile_point(double theta, double cell_radius) {
  // r = R sin θ, z = R · ½ cos θ (a0 + a1 sin²θ + a2 sin⁴θ)
  const double s = std::sin(theta), c = std::cos(theta), s2 = s * s;
  const double polynomial = evans_fung_a0 + evans_fung_a1 * s2 + evans_fung_a2 * s2 * s2;
  return {cell_radius * s, cell_radius * 0.5 * c * polynomial};
}

std::array<double, 2> rbc_profile_tangent(double theta, double cell_radius) {
  // r' = R cos θ;  z' = ½R (−sin θ P + cos θ dP/dθ),  dP/dθ = (2 a1 s + 4 a2 s³) cos θ
  const double s = std::sin(theta), c = std::cos(theta), s2 = s * s;
  const double polynomial = evans_fung_a0 + evans_fung_a1 * s2 + evans_fung_a2 * s2 * s2;
  const double polynomial_derivative = (2.0 * evans_fung_a1 * s + 4.0 * evans_fung_a2 * s2 * s) * c;
  return {cell_radius * c, 0.5 * cell_radius * (-s * polynomial + c * polynomial_derivative)};
}

std::array<double, 2> rbc_profile_normal(double theta, double cell_radius) {
  const auto t = rbc_profile_tangent(theta, cell_radius);
  const double length = std::hypot(t[0], t[1]);
  return {-t[1] / length, t[0] / length};
}

std::vector<std::array<double, 2>> rbc_inner_profile(const CellGeometry& kind, int intervals) {
  const double radius = 0.5 * kind.diameter, h = kind.shell_thickness;
  // The cavity at the axis: the centre half-thickness z(0) = ½ a0 R minus h.
  const double centre_half_thickness = rbc_profile_point(0.0, radius)[1];
  if (centre_half_thickness - h <= 0.0)
    fail(kind, "the shell thickness " + format_length(h) + " leaves no cavity at the axis: the centre thickness is " +
                   format_length(2.0 * centre_half_thickness) + " < 2h");
  std::vector<std::array<double, 2>> inner(intervals + 1), outer(intervals + 1);
  for (int k = 0; k <= intervals; ++k) {
    const double theta = pi * k / intervals;
    outer[k] = rbc_profile_point(theta, radius);
    const auto normal = rbc_profile_normal(theta, radius);
    inner[k] = {outer[k][0] - h * normal[0], outer[k][1] - h * normal[1]};
  }
  inner.front()[0] = inner.back()[0] = 0.0;  // exactly on the axis (the normal is ±z there)
  for (int k = 1; k < intervals; ++k) {
    if (!(inner[k][0] > 0.0))
      fail(kind, "the inner surface of the shell (offset inward by h = " + format_length(h) +
                     ") crosses the axis; the shell is too thick for this diameter");
    // Where the offset of a convex part folds back (curvature radius < h) the offset
    // curve runs against the outer one.
    const double along = (inner[k + 1][0] - inner[k][0]) * (outer[k + 1][0] - outer[k][0]) +
                         (inner[k + 1][1] - inner[k][1]) * (outer[k + 1][1] - outer[k][1]);
    if (!(along > 0.0))
      fail(kind, "the inner surface of the shell (offset inward by h = " + format_length(h) +
                     ") folds back near r = " + format_length(outer[k][0]) +
                     ": the profile's curvature radius there is smaller than h");
  }
  for (int i = 0; i < intervals; ++i)
    for (int j = i + 2; j < intervals; ++j)
      if (segments_meet(inner[i], inner[i + 1], inner[j], inner[j + 1]))
        fail(kind, "the inner surface of the shell (offset inward by h = " + format_length(h) +
                       ") crosses itself near r = " + format_length(inner[i][0]) + ", z = " + format_length(inner[i][1]) +
                       "; the shell is too thick for this profile");
  return inner;
}

SickleBend sickle_bend(const CellGeometry& kind) {
  SickleBend bend{0.5 * kind.length, 0.5 * kind.width, 0.5 * kind.thickness, kind.arc_radius, 0.0};
  const double a = bend.semi_length, b = bend.semi_width, c = bend.semi_thickness, rho = bend.arc_radius;
  // Ȳ = (1/V) ∫_E Y(x, y) (1 + y/ρ) dV with Y = (ρ + y) cos(x/ρ) − ρ. Over the elliptic
  // cross-section at x (semi-axes b s, c s, s² = 1 − x²/a², area A = π b c s²,
  // ∫ y dA = 0, ∫ y² dA = π (b s)³ (c s)/4) the integrand Y (1 + y/ρ) =
  // cos(x/ρ)(ρ + y)²/ρ − ρ − y integrates to cos(x/ρ)(ρ² A + ∫y² dA)/ρ − ρ A.
  const QuadratureRule rule = gauss_legendre(64);
  double moment = 0.0;
  for (std::size_t q = 0; q < rule.nodes.size(); ++q) {
    const double x = a * rule.nodes[q];
    const double s2 = 1.0 - (x / a) * (x / a);
    const double area = pi * b * c * s2;
    const double second_moment = pi * b * b * b * c * s2 * s2 / 4.0;
    moment += a * rule.weights[q] * (std::cos(x / rho) * (rho * rho * area + second_moment) / rho - rho * area);
  }
  bend.centroid_y = moment / (4.0 / 3.0 * pi * a * b * c);
  return bend;
}

std::array<double, 3> bend_sickle_point(const SickleBend& bend, const std::array<double, 3>& unbent) {
  // B(x, y, z) − (0, Ȳ, 0) = ((ρ+y) sin(x/ρ), (ρ+y) cos(x/ρ) − ρ − Ȳ, z)
  const double rho = bend.arc_radius, angle = unbent[0] / rho, radius = rho + unbent[1];
  return {radius * std::sin(angle), radius * std::cos(angle) - rho - bend.centroid_y, unbent[2]};
}

std::array<double, 3> unbend_sickle_point(const SickleBend& bend, const std::array<double, 3>& body) {
  // About the arc centre (0, −ρ − Ȳ): ρ' = distance in the x–y plane, y = ρ' − ρ,
  // x = ρ · (angle from the +y direction) = ρ atan2(X, Y + ρ + Ȳ).
  const double rho = bend.arc_radius;
  const double from_centre_x = body[0], from_centre_y = body[1] + bend.centroid_y + rho;
  return {rho * std::atan2(from_centre_x, from_centre_y), std::hypot(from_centre_x, from_centre_y) - rho, body[2]};
}

SpheroidAxes spheroid_axes(const CellGeometry& kind) {
  const double a = 0.5 * kind.diameter;
  return {a, kind.shape == CellShape::spheroid ? kind.axis_ratio * a : a};
}

void validate_cell_kind(const CellGeometry& kind) {
  const bool shell = kind.body == CellBody::shell;
  switch (kind.shape) {
    case CellShape::rbc:
      require_positive(kind, kind.diameter, "diameter");
      if (shell) {
        require_positive(kind, kind.shell_thickness, "shell thickness");
        rbc_inner_profile(kind, 512);
      }
      break;
    case CellShape::sphere:
    case CellShape::spheroid: {
      require_positive(kind, kind.diameter, "diameter");
      require_positive(kind, kind.axis_ratio, "axis ratio");
      const SpheroidAxes axes = spheroid_axes(kind);
      const double smallest_semi_axis = std::min(axes.equatorial, axes.polar);
      // Gmsh meshes the layer between two scaled spheres with slivers (smallest quality
      // 0.01–0.05 at element sizes 0.3–0.9 μm): a spheroid is a filled body.
      if (shell && kind.shape == CellShape::spheroid)
        fail(kind, "a spheroid is meshed as a filled body only (body = \"filled\")");
      if (shell) {
        require_positive(kind, kind.shell_thickness, "shell thickness");
        if (kind.shell_thickness >= smallest_semi_axis)
          fail(kind, "the shell thickness " + format_length(kind.shell_thickness) +
                         " is not smaller than the smallest semi-axis " + format_length(smallest_semi_axis));
      }
      break;
    }
    case CellShape::sickle: {
      require_positive(kind, kind.length, "length");
      require_positive(kind, kind.width, "width");
      require_positive(kind, kind.thickness, "thickness");
      require_positive(kind, kind.arc_radius, "arc radius");
      if (kind.arc_radius <= 0.5 * kind.width)
        fail(kind, "the arc radius " + format_length(kind.arc_radius) + " must exceed half the width (" +
                       format_length(0.5 * kind.width) + "): the inner side would fold over the arc centre");
      if (0.5 * kind.length >= pi * kind.arc_radius)
        fail(kind, "the length " + format_length(kind.length) + " must be shorter than 2π × arc radius (" +
                       format_length(2.0 * pi * kind.arc_radius) + "): the tips would meet");
      if (shell) {
        require_positive(kind, kind.shell_thickness, "shell thickness");
        const double smallest_semi_axis = 0.5 * std::min({kind.length, kind.width, kind.thickness});
        if (kind.shell_thickness >= smallest_semi_axis)
          fail(kind, "the shell thickness " + format_length(kind.shell_thickness) +
                         " is not smaller than the smallest semi-axis " + format_length(smallest_semi_axis));
      }
      break;
    }
  }
}

}  // namespace geometry_detail

using namespace geometry_detail;

namespace {
using Vector3 = std::array<double, 3>;
using Matrix3 = std::array<std::array<double, 3>, 3>;

Matrix3 product(const Matrix3& a, const Matrix3& b) {
  Matrix3 c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c[i][j] += a[i][k] * b[k][j];
  return c;
}

// Area of the bent ellipsoid's surface. On the ellipsoid P(θ, ψ) = (a cos θ,
// b sin θ cos ψ, c sin θ sin ψ); in the local frame (along the arc, radial, z) the bend's
// Jacobian is diag(λ, 1, 1) with λ = (ρ + y)/ρ, so the bent surface element is
// |(λ P_θx, P_θy, P_θz) × (λ P_ψx, P_ψy, P_ψz)| dθ dψ (P_ψx = 0). Gauss–Legendre in θ
// (the integrand is smooth, ∝ sin θ at the tips), the trapezoidal rule in ψ (periodic).
double bent_ellipsoid_area(double a, double b, double c, double rho) {
  const QuadratureRule rule = gauss_legendre(160);
  const int azimuths = 256;
  double area = 0.0;
  for (std::size_t q = 0; q < rule.nodes.size(); ++q) {
    const double theta = 0.5 * pi * (rule.nodes[q] + 1.0), weight = 0.5 * pi * rule.weights[q];
    const double st = std::sin(theta), ct = std::cos(theta);
    double ring = 0.0;
    for (int k = 0; k < azimuths; ++k) {
      const double psi = 2.0 * pi * k / azimuths, sp = std::sin(psi), cp = std::cos(psi);
      const double stretch = (rho + b * st * cp) / rho;
      const Vector3 along_theta{-stretch * a * st, b * ct * cp, c * ct * sp};
      const Vector3 along_psi{0.0, -b * st * sp, c * st * cp};
      const Vector3 normal{along_theta[1] * along_psi[2] - along_theta[2] * along_psi[1],
                           along_theta[2] * along_psi[0] - along_theta[0] * along_psi[2],
                           along_theta[0] * along_psi[1] - along_theta[1] * along_psi[0]};
      ring += std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    }
    area += weight * ring * (2.0 * pi / azimuths);
  }
  return area;
}

std::vector<Vector3> rbc_surface_samples(double radius, double spacing) {
  // Points equally spaced in arc length along the profile θ ∈ [0, π] (from a dense
  // table), each revolved into ⌈2πr/spacing⌉ points around the axis.
  const int table_intervals = 4096;
  std::vector<std::array<double, 2>> table(table_intervals + 1);
  std::vector<double> arc_length(table_intervals + 1, 0.0);
  for (int k = 0; k <= table_intervals; ++k) {
    table[k] = rbc_profile_point(pi * k / table_intervals, radius);
    if (k > 0)
      arc_length[k] = arc_length[k - 1] + std::hypot(table[k][0] - table[k - 1][0], table[k][1] - table[k - 1][1]);
  }
  const double total = arc_length.back();
  const int stations = std::max(2, static_cast<int>(std::ceil(total / spacing)));
  std::vector<Vector3> samples;
  std::size_t segment = 0;
  for (int k = 0; k <= stations; ++k) {
    const double target = total * k / stations;
    while (segment + 1 < static_cast<std::size_t>(table_intervals) && arc_length[segment + 1] < target) ++segment;
    const double span = arc_length[segment + 1] - arc_length[segment];
    const double t = span > 0.0 ? std::clamp((target - arc_length[segment]) / span, 0.0, 1.0) : 0.0;
    double r = table[segment][0] + t * (table[segment + 1][0] - table[segment][0]);
    const double z = table[segment][1] + t * (table[segment + 1][1] - table[segment][1]);
    if (k == 0 || k == stations) r = 0.0;
    const int around = std::max(1, static_cast<int>(std::ceil(2.0 * pi * r / spacing)));
    for (int j = 0; j < around; ++j) {
      const double phi = 2.0 * pi * (j + 0.5 * (k % 2)) / around;
      samples.push_back({r * std::cos(phi), r * std::sin(phi), z});
    }
  }
  return samples;
}

std::vector<Vector3> spheroid_surface_samples(const SpheroidAxes& axes, double spacing) {
  // Fibonacci lattice on the sphere of the larger semi-axis L: N ≈ 4πL²/spacing² points,
  // z uniform in (−1, 1), azimuth advancing by the golden angle π(3 − √5); then the unit
  // sphere scaled by (a, a, c), which moves no two points further apart than on that sphere.
  const double largest = std::max(axes.equatorial, axes.polar);
  const int count = std::max(8, static_cast<int>(std::ceil(4.0 * pi * largest * largest / (spacing * spacing))));
  const double golden_angle = pi * (3.0 - std::sqrt(5.0));
  std::vector<Vector3> samples(count);
  for (int i = 0; i < count; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / count, r = std::sqrt(std::max(0.0, 1.0 - z * z));
    samples[i] = {axes.equatorial * r * std::cos(golden_angle * i), axes.equatorial * r * std::sin(golden_angle * i),
                  axes.polar * z};
  }
  return samples;
}

std::vector<Vector3> sickle_surface_samples(const SickleBend& bend, double spacing) {
  // Rings of the unbent ellipsoid at x = a cos θ (semi-axes b sin θ, c sin θ), bent. The θ
  // step keeps the bent meridians at most `spacing` apart (their speed is at most
  // √((λ_max a)² + max(b, c)²), λ_max = (ρ + b)/ρ); points around a ring ≈ its perimeter
  // (Ramanujan's approximation) / spacing.
  const double a = bend.semi_length, b = bend.semi_width, c = bend.semi_thickness, rho = bend.arc_radius;
  const double max_speed = std::hypot((rho + b) / rho * a, std::max(b, c));
  const int rings = std::max(2, static_cast<int>(std::ceil(pi * max_speed / spacing)));
  std::vector<Vector3> samples;
  for (int k = 0; k <= rings; ++k) {
    const double theta = pi * k / rings, st = (k == 0 || k == rings) ? 0.0 : std::sin(theta);
    const double x = a * std::cos(theta), p = b * st, q = c * st;
    const double perimeter = pi * (3.0 * (p + q) - std::sqrt((3.0 * p + q) * (p + 3.0 * q)));
    const int around = st == 0.0 ? 1 : std::max(3, static_cast<int>(std::ceil(perimeter / spacing)));
    for (int j = 0; j < around; ++j) {
      const double psi = 2.0 * pi * (j + 0.5 * (k % 2)) / around;
      samples.push_back(bend_sickle_point(bend, {x, p * std::cos(psi), q * std::sin(psi)}));
    }
  }
  return samples;
}
}  // namespace

double evans_fung_half_thickness(double radius_from_axis, double cell_radius) {
  // z = R y(x), x = r/R, y = ½ √(1 − x²)(a0 + a1 x² + a2 x⁴); zero on and beyond the rim.
  const double x = radius_from_axis / cell_radius;
  if (!(std::abs(x) < 1.0)) return 0.0;
  const double x2 = x * x;
  return cell_radius * 0.5 * std::sqrt(1.0 - x2) * (0.207 + 2.002 * x2 - 1.122 * x2 * x2);
}

namespace {
// ∫₀^{π/2} g(θ) dθ by `points`-point Gauss–Legendre quadrature.
template <class Integrand>
double integrate_over_quarter_turn(int points, const Integrand& g) {
  const QuadratureRule rule = gauss_legendre(points);
  double integral = 0.0;
  for (std::size_t q = 0; q < rule.nodes.size(); ++q)
    integral += 0.25 * pi * rule.weights[q] * g(0.25 * pi * (rule.nodes[q] + 1.0));
  return integral;
}
}  // namespace

double exact_cell_volume(const CellGeometry& kind) {
  validate_cell_kind(kind);
  switch (kind.shape) {
    case CellShape::rbc: {
      // V = 2 ∫₀^R 2π r z(r) dr; with r = R sin θ, z = ½R cos θ P(sin²θ):
      // V = 2π R³ ∫₀^{π/2} sin θ cos²θ P(sin²θ) dθ (smooth: no √ singularity left).
      const double radius = 0.5 * kind.diameter;
      return 2.0 * integrate_over_quarter_turn(48, [&](double theta) {
        const auto point = rbc_profile_point(theta, radius);
        const double dr_dtheta = radius * std::cos(theta);
        return 2.0 * pi * point[0] * point[1] * dr_dtheta;
      });
    }
    case CellShape::sphere:
    case CellShape::spheroid: {
      // V = (4/3)π a² c.
      const SpheroidAxes axes = spheroid_axes(kind);
      return 4.0 / 3.0 * pi * axes.equatorial * axes.equatorial * axes.polar;
    }
    case CellShape::sickle:
      // The bend keeps the ellipsoid's volume (see the top of this file): V = (4/3)π a b c.
      return 4.0 / 3.0 * pi * (0.5 * kind.length) * (0.5 * kind.width) * (0.5 * kind.thickness);
  }
  return 0.0;
}

double exact_cell_area(const CellGeometry& kind) {
  validate_cell_kind(kind);
  switch (kind.shape) {
    case CellShape::rbc: {
      // A = 2 ∫₀^{π/2} 2π r(θ) |(r'(θ), z'(θ))| dθ (upper half, doubled).
      const double radius = 0.5 * kind.diameter;
      return 2.0 * integrate_over_quarter_turn(64, [&](double theta) {
        const auto point = rbc_profile_point(theta, radius);
        const auto tangent = rbc_profile_tangent(theta, radius);
        return 2.0 * pi * point[0] * std::hypot(tangent[0], tangent[1]);
      });
    }
    case CellShape::sphere:
    case CellShape::spheroid: {
      // With e the eccentricity of the meridian ellipse:
      //   oblate (c < a), e² = 1 − c²/a²:   A = 2πa² + 2π c² atanh(e)/e,
      //   prolate (c > a), e² = 1 − a²/c²:  A = 2πa² + 2π a c asin(e)/e,
      // both → 4πa² as e → 0 (atanh(e)/e, asin(e)/e → 1), the sphere.
      const SpheroidAxes axes = spheroid_axes(kind);
      const double a = axes.equatorial, c = axes.polar;
      if (c == a) return 4.0 * pi * a * a;
      if (c < a) {
        const double e = std::sqrt(1.0 - (c * c) / (a * a));
        return 2.0 * pi * a * a + 2.0 * pi * c * c * std::atanh(e) / e;
      }
      const double e = std::sqrt(1.0 - (a * a) / (c * c));
      return 2.0 * pi * a * a + 2.0 * pi * a * c * std::asin(e) / e;
    }
    case CellShape::sickle: {
      const SickleBend bend = sickle_bend(kind);
      return bent_ellipsoid_area(bend.semi_length, bend.semi_width, bend.semi_thickness, bend.arc_radius);
    }
  }
  return 0.0;
}

bool inside_cell(const CellGeometry& kind, const std::array<double, 3>& p) {
  switch (kind.shape) {
    case CellShape::rbc: {
      // Inside when r < R and |z| < R y(r/R).
      const double radius = 0.5 * kind.diameter, r = std::hypot(p[0], p[1]);
      return r < radius && std::abs(p[2]) < evans_fung_half_thickness(r, radius);
    }
    case CellShape::sphere:
    case CellShape::spheroid: {
      // Inside when (x² + y²)/a² + z²/c² < 1.
      const SpheroidAxes axes = spheroid_axes(kind);
      const double a = axes.equatorial, c = axes.polar;
      return (p[0] * p[0] + p[1] * p[1]) / (a * a) + p[2] * p[2] / (c * c) < 1.0;
    }
    case CellShape::sickle: {
      // The bend (its centroid shift is a quadrature) of the last sickle asked about: the
      // placement check asks about one kind many thousand times in a row.
      thread_local std::array<double, 4> last_sizes{-1.0, -1.0, -1.0, -1.0};
      thread_local SickleBend last_bend{};
      const std::array<double, 4> sizes{kind.length, kind.width, kind.thickness, kind.arc_radius};
      if (sizes != last_sizes) last_bend = sickle_bend(kind), last_sizes = sizes;
      const SickleBend& bend = last_bend;
      const auto q = unbend_sickle_point(bend, p);
      const double x = q[0] / bend.semi_length, y = q[1] / bend.semi_width, z = q[2] / bend.semi_thickness;
      return x * x + y * y + z * z < 1.0;
    }
  }
  return false;
}

std::vector<std::array<double, 3>> cell_surface_samples(const CellGeometry& kind, double spacing) {
  validate_cell_kind(kind);
  if (!(spacing > 0.0 && std::isfinite(spacing)))
    throw std::invalid_argument("cell_surface_samples: the spacing must be positive, not " + std::to_string(spacing));
  // No body holds more surface than the sphere of its largest extent D (a prolate
  // spheroid's is its length), π D²: past a few million samples the cell is far larger
  // than any mesh could resolve (and sampling it would exhaust the memory before the
  // placement check could say so).
  constexpr double most_samples = 2e6;
  const double largest_extent =
      kind.shape == CellShape::spheroid ? kind.diameter * std::max(1.0, kind.axis_ratio) : kind.diameter;
  const double estimated_samples = pi * largest_extent * largest_extent / (spacing * spacing);
  if (estimated_samples > most_samples) {
    std::ostringstream reason;
    reason << "the largest extent " << largest_extent << " um would need about " << std::setprecision(2) << estimated_samples
           << " surface samples at the placement check's spacing of " << spacing
           << " um (at most 2e+06): the cell is too large";
    throw std::runtime_error(reason.str());
  }
  switch (kind.shape) {
    case CellShape::rbc: return rbc_surface_samples(0.5 * kind.diameter, spacing);
    case CellShape::sphere:
    case CellShape::spheroid: return spheroid_surface_samples(spheroid_axes(kind), spacing);
    case CellShape::sickle: return sickle_surface_samples(sickle_bend(kind), spacing);
  }
  return {};
}

std::array<std::array<double, 3>, 3> placement_rotation(const std::array<double, 3>& orientation_deg) {
  // R = Rz(γ) Ry(β) Rx(α): rotate about the fixed x axis first, then y, then z.
  const double degree = pi / 180.0;
  const double alpha = orientation_deg[0] * degree, beta = orientation_deg[1] * degree,
               gamma = orientation_deg[2] * degree;
  const Matrix3 rx{{{1, 0, 0}, {0, std::cos(alpha), -std::sin(alpha)}, {0, std::sin(alpha), std::cos(alpha)}}};
  const Matrix3 ry{{{std::cos(beta), 0, std::sin(beta)}, {0, 1, 0}, {-std::sin(beta), 0, std::cos(beta)}}};
  const Matrix3 rz{{{std::cos(gamma), -std::sin(gamma), 0}, {std::sin(gamma), std::cos(gamma), 0}, {0, 0, 1}}};
  return product(rz, product(ry, rx));
}

}  // namespace rouleau
