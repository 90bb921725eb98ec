#pragma once
// The case-file spelling of every choice ("periodic", "bdf2", "auto", ...): one table per
// enum, which the loader accepts, the resolved case writes and the case-file reference
// lists, in the order error messages list them. The geometry's enums keep theirs beside
// them (geometry/cell_geometry.hpp, geometry/vessel_profile.hpp).
// Host-only: includes no Kokkos header.
#include <algorithm>
#include <array>
#include <initializer_list>
#include <optional>
#include <string_view>
#include <vector>

#include "config/case_config.hpp"
#include "geometry/named_choice.hpp"

namespace rouleau {

inline constexpr std::array<NamedChoice<BoundaryType>, 4> boundary_type_names{
    {{BoundaryType::periodic, "periodic"},
     {BoundaryType::wall, "wall"},
     {BoundaryType::inflow, "inflow"},
     {BoundaryType::traction, "traction"}}};
inline constexpr std::array<NamedChoice<InflowProfile>, 2> inflow_profile_names{
    {{InflowProfile::uniform, "uniform"}, {InflowProfile::parabolic, "parabolic"}}};
inline constexpr std::array<NamedChoice<TimeMode>, 2> time_mode_names{
    {{TimeMode::steady, "steady"}, {TimeMode::transient, "transient"}}};
inline constexpr std::array<NamedChoice<TimeScheme>, 2> time_scheme_names{
    {{TimeScheme::bdf2, "bdf2"}, {TimeScheme::backward_euler, "backward_euler"}}};
inline constexpr std::array<NamedChoice<StokesChoice>, 3> stokes_choice_names{
    {{StokesChoice::automatic, "auto"}, {StokesChoice::on, "on"}, {StokesChoice::off, "off"}}};
inline constexpr std::array<NamedChoice<PreconditionerType>, 6> preconditioner_names{
    {{PreconditionerType::automatic, "auto"},
     {PreconditionerType::ilu0, "ilu0"},
     {PreconditionerType::fast_diagonalization, "fast_diagonalization"},
     {PreconditionerType::multigrid, "multigrid"},
     {PreconditionerType::block_jacobi, "block_jacobi"},
     {PreconditionerType::none, "none"}}};
inline constexpr std::array<NamedChoice<MultigridSmoother>, 2> multigrid_smoother_names{
    {{MultigridSmoother::block_jacobi, "block_jacobi"}, {MultigridSmoother::ilu0, "ilu0"}}};
inline constexpr std::array<NamedChoice<MultigridPrecision>, 2> multigrid_precision_names{
    {{MultigridPrecision::single_precision, "single"}, {MultigridPrecision::double_precision, "double"}}};
inline constexpr std::array<NamedChoice<InteractionQuadrature>, 4> interaction_quadrature_names{
    {{InteractionQuadrature::automatic, "auto"},
     {InteractionQuadrature::nodes, "nodes"},
     {InteractionQuadrature::gauss3, "gauss3"},
     {InteractionQuadrature::gauss6, "gauss6"}}};
inline constexpr std::array<NamedChoice<CouplingScheme>, 2> coupling_scheme_names{
    {{CouplingScheme::explicit_forces, "explicit"}, {CouplingScheme::semi_implicit, "semi_implicit"}}};
inline constexpr std::array<NamedChoice<FilmModel>, 2> film_model_names{
    {{FilmModel::rigid, "rigid"}, {FilmModel::deforming, "deforming"}}};

// The table of each enum, found by the enum's type.
constexpr const auto& named_choices(BoundaryType) { return boundary_type_names; }
constexpr const auto& named_choices(InflowProfile) { return inflow_profile_names; }
constexpr const auto& named_choices(TimeMode) { return time_mode_names; }
constexpr const auto& named_choices(TimeScheme) { return time_scheme_names; }
constexpr const auto& named_choices(StokesChoice) { return stokes_choice_names; }
constexpr const auto& named_choices(PreconditionerType) { return preconditioner_names; }
constexpr const auto& named_choices(MultigridSmoother) { return multigrid_smoother_names; }
constexpr const auto& named_choices(MultigridPrecision) { return multigrid_precision_names; }
constexpr const auto& named_choices(InteractionQuadrature) { return interaction_quadrature_names; }
constexpr const auto& named_choices(CouplingScheme) { return coupling_scheme_names; }
constexpr const auto& named_choices(FilmModel) { return film_model_names; }
constexpr const auto& named_choices(CellShape) { return cell_shape_names; }
constexpr const auto& named_choices(CellBody) { return cell_body_names; }
constexpr const auto& named_choices(MeshResolution) { return mesh_resolution_names; }
constexpr const auto& named_choices(VesselTransition) { return vessel_transition_names; }

// The case-file spelling of `value`.
template <class Enum>
constexpr const char* toml_name(Enum value) {
  return name_of(named_choices(value), value);
}

// The value spelled `name`, if any.
template <class Enum>
std::optional<Enum> enum_named(std::string_view name) {
  for (const NamedChoice<Enum>& choice : named_choices(Enum{}))
    if (name == choice.name) return choice.value;
  return std::nullopt;
}

// The spellings of `values` (all of the enum's when empty), in the table's order.
template <class Enum>
std::vector<std::string_view> spellings(std::initializer_list<Enum> values = {}) {
  std::vector<std::string_view> names;
  for (const NamedChoice<Enum>& choice : named_choices(Enum{}))
    if (values.size() == 0 || std::find(values.begin(), values.end(), choice.value) != values.end())
      names.emplace_back(choice.name);
  return names;
}

}  // namespace rouleau
