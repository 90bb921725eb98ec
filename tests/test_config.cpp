// The case-file loader: converted values, every class of bad input, overrides, the derived
// scales, the cell kinds and cells, and the resolved-case round trip.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "bad_case_files.hpp"
#include "config/cell_kinds.hpp"
#include "config/derived.hpp"
#include "config/load_case.hpp"
#include "config/resolved_case.hpp"
#include "config/scene_plan.hpp"
#include "geometry/grading.hpp"
#include "util/errors.hpp"
#include "temporary_folder.hpp"

namespace {

using rouleau::BoundaryType;
using rouleau::CaseConfig;
using rouleau::CellKindConfig;
using rouleau::InputError;

const std::string data_dir = ROULEAU_TEST_DATA_DIR;
const std::string good_case = data_dir + "/good_case.toml";

// Writes `text` to a fresh file in a per-test temporary folder; returns its path.
std::string write_case_file(const std::string& file_name, const std::string& text) {
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto folder = rouleau::testing::temporary_folder("config_" + std::string(test->name()));
  const std::string path = (folder / file_name).string();
  std::ofstream(path) << text;
  return path;
}

// The smallest valid case: the required keys only.
const std::string minimal_case =
    "[domain]\nlower_um = [0, 0, 0]\nupper_um = [10, 20, 30]\nelements = [2, 2, 2]\n"
    "[time]\ndt_s = 0.01\nend_s = 0.1\n";

// Loads and returns the InputError it throws (fails the test when nothing is thrown).
InputError load_error(const std::string& path, const std::vector<std::string>& overrides = {}) {
  try {
    rouleau::load_case(path, overrides);
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "load_case(" << path << ") accepted bad input";
  return InputError("", "", "");
}


// Every field of two cases (source_file aside) is exactly equal.
void expect_identical_cases(const CaseConfig& a, const CaseConfig& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.description, b.description);
  EXPECT_EQ(a.fluid.density, b.fluid.density);
  EXPECT_EQ(a.fluid.viscosity, b.fluid.viscosity);
  EXPECT_EQ(a.fluid.body_force, b.fluid.body_force);
  EXPECT_EQ(a.domain.lower, b.domain.lower);
  EXPECT_EQ(a.domain.upper, b.domain.upper);
  EXPECT_EQ(a.domain.elements, b.domain.elements);
  EXPECT_EQ(a.domain.wall_grading, b.domain.wall_grading);
  for (int side = 0; side < 6; ++side) {
    SCOPED_TRACE(rouleau::side_names[side]);
    const auto &first = a.domain.boundary[side], &second = b.domain.boundary[side];
    EXPECT_EQ(first.type, second.type);
    EXPECT_EQ(first.velocity, second.velocity);
    EXPECT_EQ(first.mean_speed, second.mean_speed);
    EXPECT_EQ(first.profile, second.profile);
    EXPECT_EQ(first.pressure, second.pressure);
    EXPECT_EQ(first.parallel_flow, second.parallel_flow);
  }
  EXPECT_EQ(a.time.mode, b.time.mode);
  EXPECT_EQ(a.time.scheme, b.time.scheme);
  EXPECT_EQ(a.time.dt, b.time.dt);
  EXPECT_EQ(a.time.end, b.time.end);
  EXPECT_EQ(a.solver.stokes, b.solver.stokes);
  EXPECT_EQ(a.solver.stokes_reynolds_threshold, b.solver.stokes_reynolds_threshold);
  EXPECT_EQ(a.solver.newton_rtol, b.solver.newton_rtol);
  EXPECT_EQ(a.solver.newton_atol, b.solver.newton_atol);
  EXPECT_EQ(a.solver.newton_step_rtol, b.solver.newton_step_rtol);
  EXPECT_EQ(a.solver.newton_max_iterations, b.solver.newton_max_iterations);
  EXPECT_EQ(a.solver.gmres_restart, b.solver.gmres_restart);
  EXPECT_EQ(a.solver.gmres_rtol, b.solver.gmres_rtol);
  EXPECT_EQ(a.solver.gmres_max_iterations, b.solver.gmres_max_iterations);
  EXPECT_EQ(a.solver.preconditioner, b.solver.preconditioner);
  EXPECT_EQ(a.scales.length, b.scales.length);
  EXPECT_EQ(a.scales.velocity, b.scales.velocity);
  EXPECT_EQ(a.output.write_fields, b.output.write_fields);
  EXPECT_EQ(a.output.fields_every_steps, b.output.fields_every_steps);
  EXPECT_EQ(a.output.diagnostics_every_steps, b.output.diagnostics_every_steps);
  EXPECT_EQ(a.output.cell_gaps_max_cells, b.output.cell_gaps_max_cells);
  EXPECT_EQ(a.checkpoint.every_steps, b.checkpoint.every_steps);
  EXPECT_EQ(a.checkpoint.every_minutes, b.checkpoint.every_minutes);
  EXPECT_EQ(a.checkpoint.kept, b.checkpoint.kept);
  ASSERT_EQ(a.cell_kinds.size(), b.cell_kinds.size());
  for (std::size_t i = 0; i < a.cell_kinds.size(); ++i) {
    const CellKindConfig &first = a.cell_kinds[i], &second = b.cell_kinds[i];
    SCOPED_TRACE("cell kind " + first.name);
    EXPECT_EQ(first.name, second.name);
    EXPECT_EQ(first.shape, second.shape);
    EXPECT_EQ(first.body, second.body);
    EXPECT_EQ(first.diameter, second.diameter);
    EXPECT_EQ(first.length, second.length);
    EXPECT_EQ(first.width, second.width);
    EXPECT_EQ(first.thickness, second.thickness);
    EXPECT_EQ(first.arc_radius, second.arc_radius);
    EXPECT_EQ(first.shell_thickness, second.shell_thickness);
    EXPECT_EQ(first.resolution, second.resolution);
    EXPECT_EQ(first.mesh_size, second.mesh_size);
    EXPECT_EQ(first.shear_modulus, second.shear_modulus);
    EXPECT_EQ(first.bulk_modulus, second.bulk_modulus);
    EXPECT_EQ(first.poisson_ratio, second.poisson_ratio);
    EXPECT_EQ(first.density, second.density);
    EXPECT_EQ(first.morse_well_depth_factor, second.morse_well_depth_factor);
    EXPECT_EQ(first.strain_hardening_ratio, second.strain_hardening_ratio);
    EXPECT_EQ(first.area_modulus, second.area_modulus);
    EXPECT_EQ(first.volume_modulus, second.volume_modulus);
  }
  ASSERT_EQ(a.cells.size(), b.cells.size());
  for (std::size_t i = 0; i < a.cells.size(); ++i) {
    SCOPED_TRACE("cell " + std::to_string(i));
    EXPECT_EQ(a.cells[i].kind, b.cells[i].kind);
    EXPECT_EQ(a.cells[i].center, b.cells[i].center);
    EXPECT_EQ(a.cells[i].orientation, b.cells[i].orientation);
  }
  const auto expect_same_morse = [](const rouleau::MorseConfig& x, const rouleau::MorseConfig& y) {
    EXPECT_EQ(x.well_depth, y.well_depth);
    EXPECT_EQ(x.beta, y.beta);
    EXPECT_EQ(x.zero_force_length, y.zero_force_length);
    EXPECT_EQ(x.cutoff, y.cutoff);
  };
  EXPECT_EQ(a.interaction.enabled, b.interaction.enabled);
  EXPECT_EQ(a.interaction.quadrature, b.interaction.quadrature);
  EXPECT_EQ(a.interaction.strength, b.interaction.strength);
  EXPECT_EQ(a.interaction.skin, b.interaction.skin);
  expect_same_morse(a.interaction.morse, b.interaction.morse);
  EXPECT_EQ(a.coupling.support_elements, b.coupling.support_elements);
  EXPECT_EQ(a.coupling.stable_step_factor, b.coupling.stable_step_factor);
  EXPECT_EQ(a.coupling.allow_unstable_step, b.coupling.allow_unstable_step);
  EXPECT_EQ(a.coupling.gravity, b.coupling.gravity);
  EXPECT_EQ(a.scene.skip_unneeded_stages, b.scene.skip_unneeded_stages);
  ASSERT_EQ(a.interaction.pairs.size(), b.interaction.pairs.size());
  for (std::size_t i = 0; i < a.interaction.pairs.size(); ++i) {
    EXPECT_EQ(a.interaction.pairs[i].kind_a, b.interaction.pairs[i].kind_a);
    EXPECT_EQ(a.interaction.pairs[i].kind_b, b.interaction.pairs[i].kind_b);
    expect_same_morse(a.interaction.pairs[i].morse, b.interaction.pairs[i].morse);
  }
}

// The kind called `name` of a loaded case (fails the test when there is none).
const CellKindConfig& kind_of(const CaseConfig& config, const std::string& name) {
  const CellKindConfig* kind = rouleau::find_cell_kind(config, name);
  if (!kind) {
    ADD_FAILURE() << "no cell kind " << name;
    static const CellKindConfig none;
    return none;
  }
  return *kind;
}

TEST(ConfigLoad, GoodCaseHasTheConvertedValues) {
  const CaseConfig config = rouleau::load_case(good_case);
  EXPECT_EQ(config.source_file, good_case);
  EXPECT_EQ(config.name, "shear_box");
  EXPECT_DOUBLE_EQ(config.fluid.density, 1.025e-9);  // 1025 kg/m³ (an integer) in pN·s²/μm⁴
  EXPECT_DOUBLE_EQ(config.fluid.viscosity, 1.2e-3);
  EXPECT_EQ(config.domain.lower, (std::array<double, 3>{0, -10, 0}));
  EXPECT_EQ(config.domain.upper, (std::array<double, 3>{40, 10, 20}));
  EXPECT_EQ(config.domain.elements, (std::array<int, 3>{8, 16, 4}));
  EXPECT_EQ(config.domain.wall_grading, (std::array<double, 3>{1, 2.5, 1}));
  EXPECT_EQ(config.domain.boundary[rouleau::x_min].type, BoundaryType::periodic);
  EXPECT_EQ(config.domain.boundary[rouleau::z_max].type, BoundaryType::periodic);
  EXPECT_EQ(config.domain.boundary[rouleau::y_min].type, BoundaryType::wall);
  EXPECT_EQ(config.domain.boundary[rouleau::y_min].velocity, (std::array<double, 3>{-5, 0, 0}));
  EXPECT_EQ(config.domain.boundary[rouleau::y_max].velocity, (std::array<double, 3>{5, 0, 0}));
  EXPECT_EQ(config.time.mode, rouleau::TimeMode::transient);
  EXPECT_EQ(config.time.scheme, rouleau::TimeScheme::backward_euler);
  EXPECT_DOUBLE_EQ(config.time.dt, 0.005);
  EXPECT_DOUBLE_EQ(config.time.end, 0.5);
  EXPECT_DOUBLE_EQ(config.solver.newton_rtol, 1e-7);
  EXPECT_EQ(config.solver.gmres_restart, 40);
  EXPECT_EQ(config.solver.preconditioner, rouleau::PreconditionerType::none);
  EXPECT_FALSE(config.output.write_fields);
  EXPECT_EQ(config.output.fields_every_steps, 10);
  // keys the file leaves out keep the struct defaults
  const rouleau::SolverConfig default_solver{};
  EXPECT_EQ(config.solver.newton_atol, default_solver.newton_atol);
  EXPECT_EQ(config.solver.gmres_max_iterations, default_solver.gmres_max_iterations);
  EXPECT_EQ(config.output.diagnostics_every_steps, 1);
}

TEST(ConfigLoad, MinimalCaseTakesDefaultsAndItsNameFromTheFile) {
  const CaseConfig config = rouleau::load_case(write_case_file("tiny_box.toml", minimal_case));
  EXPECT_EQ(config.name, "tiny_box");
  for (const auto& side : config.domain.boundary) {
    EXPECT_EQ(side.type, BoundaryType::wall);
    EXPECT_EQ(side.velocity, (std::array<double, 3>{0, 0, 0}));
  }
  EXPECT_EQ(config.fluid.density, rouleau::FluidConfig{}.density);
}

TEST(ConfigLoad, SteadyCaseNeedsNoTimeStep) {
  const std::string path = write_case_file(
      "steady.toml", "[domain]\nlower_um = [0, 0, 0]\nupper_um = [1, 1, 1]\nelements = [2, 2, 2]\n"
                     "[time]\nmode = \"steady\"\n");
  EXPECT_EQ(rouleau::load_case(path).time.mode, rouleau::TimeMode::steady);
}

// Every file in tests/data/bad_cases is one class of bad input; each names the key its
// error must carry ("# expect-key:").
TEST(ConfigLoad, EveryBadCaseFileIsAnInputErrorNamingFileAndKey) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(data_dir + "/bad_cases")) {
    const std::string path = entry.path().string();
    SCOPED_TRACE(path);
    const std::string expected_key = expected_key_of(path);
    ASSERT_FALSE(expected_key.empty()) << "no '# expect-key:' line";
    const InputError error = load_error(path);
    EXPECT_EQ(error.file(), path);
    EXPECT_EQ(error.key().rfind(expected_key, 0), 0u) << "key " << error.key();
    EXPECT_NE(std::string(error.what()).find(path + ": " + expected_key), std::string::npos) << error.what();
    EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos) << "not one line: " << error.what();
    ++files;
  }
  EXPECT_GE(files, 25);
}

TEST(ConfigLoad, ReasonsSayWhatIsWrong) {
  const auto reason_of = [](const std::string& bad_case) { return load_error(data_dir + "/bad_cases/" + bad_case).reason(); };
  EXPECT_EQ(reason_of("negative_viscosity.toml"), "must be > 0, got -1");
  EXPECT_EQ(reason_of("wrong_type.toml"), "expected a number, got a string");
  EXPECT_EQ(reason_of("unknown_key.toml"), "unknown key; did you mean \"viscosity_Pa_s\"?");
  EXPECT_EQ(reason_of("unknown_table.toml"), "unknown table; did you mean \"fluid\"?");
  EXPECT_EQ(reason_of("missing_required_key.toml"), "missing required key");
  EXPECT_EQ(reason_of("wrong_array_length.toml"), "expected an array of 3 numbers, got 2 elements");
  EXPECT_NE(reason_of("syntax_error.toml").find("TOML syntax error"), std::string::npos);
  EXPECT_NE(reason_of("key_of_other_boundary_type.toml").find("does not belong to boundary type \"inflow\""),
            std::string::npos);
  EXPECT_NE(reason_of("unpaired_periodic.toml").find("boundary.x_min is periodic"), std::string::npos);
}

TEST(ConfigLoad, CellErrorsSayWhatIsWrong) {
  const auto reason_of = [](const std::string& bad_case) { return load_error(data_dir + "/bad_cases/" + bad_case).reason(); };
  EXPECT_EQ(reason_of("negative_shear_modulus.toml"), "must be > 0, got -11.7");
  EXPECT_EQ(reason_of("zero_bulk_modulus.toml"), "must be > 0, got 0");
  EXPECT_EQ(reason_of("both_shear_moduli.toml"),
            "give either shear_modulus_Pa or membrane_shear_modulus_pN_um, not both");
  EXPECT_EQ(reason_of("membrane_modulus_on_filled_body.toml"),
            "applies to body = \"shell\" only, and this kind's body is \"filled\" (give shear_modulus_Pa)");
  EXPECT_EQ(reason_of("poisson_ratio_one_half.toml"), "must be > -1 and < 0.5, got 0.5");
  EXPECT_EQ(reason_of("unknown_cell_shape.toml"),
            "must be one of \"rbc\", \"sickle\", \"sphere\", \"spheroid\"; got \"rbd\"; did you mean \"rbc\"?");
  EXPECT_EQ(reason_of("unknown_cell_kind.toml"),
            "must be one of \"normal\", \"sickle\", \"capsule\"; got \"sickel\"; did you mean \"sickle\"?");
  EXPECT_EQ(reason_of("cells_not_array_of_tables.toml"), "expected an array of tables ([[cells]] entries), got a table");
  EXPECT_EQ(reason_of("cell_entry_not_a_table.toml"),
            "expected a table (an entry of an array of tables ([[cells]] entries)), got an integer");
  EXPECT_EQ(reason_of("cell_without_center.toml"), "missing required key");
  // the limit is half the Evans–Fung disc's thickness on its axis: 0.1035 × 7.82 / 2 μm
  EXPECT_EQ(reason_of("shell_thicker_than_rbc_centre.toml"),
            "must be < 0.404685 μm, half the disc's thickness on its axis (0.1035 × diameter_um = 0.80937 μm), "
            "got 0.45");
  EXPECT_EQ(reason_of("sickle_arc_radius_too_small.toml"),
            "must be > width_um / 2 = 2.1 μm (else the crescent's inner edge crosses its centre of curvature), "
            "got 2");
  EXPECT_EQ(reason_of("unknown_cell_kind_key.toml"), "unknown key; did you mean \"diameter_um\"?");
  EXPECT_EQ(reason_of("size_key_of_other_shape.toml"), "does not belong to shape \"sphere\" (its size keys are diameter_um)");
  EXPECT_EQ(reason_of("negative_cell_diameter.toml"), "must be > 0, got -7.82");
}

TEST(ConfigLoad, SyntaxErrorNamesLineAndColumn) {
  const InputError error = load_error(data_dir + "/bad_cases/syntax_error.toml");
  EXPECT_TRUE(std::regex_match(error.key(), std::regex("line 4, column [0-9]+"))) << error.key();
}

TEST(ConfigLoad, MissingFileIsAnInputErrorOnTheFile) {
  const std::string path = data_dir + "/no_such_case.toml";
  const InputError error = load_error(path);
  EXPECT_EQ(error.file(), path);
  EXPECT_EQ(error.key(), "(file)");
  EXPECT_EQ(load_error(data_dir).key(), "(file)");  // a directory is not a case file
}

TEST(ConfigLoad, DerivedTableIsIgnored) {
  const std::string path =
      write_case_file("with_derived.toml", minimal_case + "[derived]\nreynolds = 12.0\nanything = \"goes\"\n");
  EXPECT_EQ(rouleau::load_case(path).name, "with_derived");
}

TEST(ConfigOverrides, ValuesOfEveryKindAreApplied) {
  const CaseConfig config = rouleau::load_case(
      good_case, {"time.dt_s=0.01", "boundary.y_max.velocity_um_s=[7,0,0]", "case.name=\"renamed\"",
                  "time.mode=steady", "scales.length_um = 4", "output.fields=true", "solver.gmres_restart=12"});
  EXPECT_DOUBLE_EQ(config.time.dt, 0.01);
  EXPECT_EQ(config.domain.boundary[rouleau::y_max].velocity, (std::array<double, 3>{7, 0, 0}));
  EXPECT_EQ(config.name, "renamed");
  EXPECT_EQ(config.time.mode, rouleau::TimeMode::steady);  // a bare word is a string
  EXPECT_DOUBLE_EQ(config.scales.length, 4.0);             // [scales] created by the override
  EXPECT_TRUE(config.output.write_fields);
  EXPECT_EQ(config.solver.gmres_restart, 12);
}

TEST(ConfigOverrides, LaterOverridesWinAndInlineTablesReplaceSides) {
  const CaseConfig config = rouleau::load_case(
      good_case, {"time.dt_s=0.01", "time.dt_s=0.02",
                  "boundary.y_min={type=\"inflow\", mean_speed_um_s=3, profile=\"uniform\"}"});
  EXPECT_DOUBLE_EQ(config.time.dt, 0.02);
  const auto& side = config.domain.boundary[rouleau::y_min];
  EXPECT_EQ(side.type, BoundaryType::inflow);
  EXPECT_DOUBLE_EQ(side.mean_speed, 3.0);
  EXPECT_EQ(side.profile, rouleau::InflowProfile::uniform);
}

TEST(ConfigOverrides, BadOverridesNameTheSetOptionAndTheKey) {
  struct BadOverride {
    std::string text, key;
  };
  const std::vector<BadOverride> bad_overrides{
      {"fluid.viscosity_Pa_s=-1", "fluid.viscosity_Pa_s"},      // out of range
      {"fluid.viscosty_Pa_s=1e-3", "fluid.viscosty_Pa_s"},      // unknown key
      {"fluids.viscosity_Pa_s=1e-3", "fluids"},                 // unknown table
      {"time.dt_s=fast", "time.dt_s"},                          // a string for a number
      {"domain.lower_um=[0,0]", "domain.lower_um"},             // wrong array length
      {"fluid.viscosity_Pa_s.value=1", "fluid.viscosity_Pa_s"}, // through a value
      {"time.dt_s", "time.dt_s"},                               // no '='
      {"time..dt_s=1", "time..dt_s"},                           // not a dotted key
  };
  for (const auto& bad : bad_overrides) {
    SCOPED_TRACE(bad.text);
    const InputError error = load_error(good_case, {bad.text});
    EXPECT_EQ(error.file(), "--set");
    EXPECT_EQ(error.key(), bad.key);
  }
}

TEST(ConfigOverrides, ErrorsInTheFileStillNameTheFile) {
  const InputError error = load_error(data_dir + "/bad_cases/negative_viscosity.toml", {"time.dt_s=0.02"});
  EXPECT_EQ(error.file(), data_dir + "/bad_cases/negative_viscosity.toml");
  EXPECT_EQ(error.key(), "fluid.viscosity_Pa_s");
}

TEST(ConfigDerived, ShearBoxScalesFromTheWallsAndTheBoundedDirection) {
  const CaseConfig config = rouleau::load_case(good_case);
  const auto derived = rouleau::derive_quantities(config);
  EXPECT_DOUBLE_EQ(derived.length_scale, 20.0);  // y: x and z are periodic
  EXPECT_DOUBLE_EQ(derived.velocity_scale, 5.0);
  EXPECT_DOUBLE_EQ(derived.pressure_scale, 1.2e-3 * 5.0 / 20.0);
  EXPECT_DOUBLE_EQ(derived.reynolds, 1.025e-9 * 5.0 * 20.0 / 1.2e-3);
  EXPECT_TRUE(derived.stokes);
  EXPECT_EQ(derived.stokes_reason,
            "Re = 8.5e-05 < threshold 0.01: convective term dropped (changes the answer by O(Re)); "
            "set solver.stokes = \"off\" to keep it");
}

TEST(ConfigDerived, StokesChoiceAndThreshold) {
  EXPECT_FALSE(rouleau::derive_quantities(rouleau::load_case(good_case, {"solver.stokes=off"})).stokes);
  EXPECT_TRUE(rouleau::derive_quantities(rouleau::load_case(good_case, {"solver.stokes=on"})).stokes);
  const auto above_threshold =
      rouleau::derive_quantities(rouleau::load_case(good_case, {"solver.stokes_reynolds_threshold=1e-6"}));
  EXPECT_FALSE(above_threshold.stokes);
  EXPECT_NE(above_threshold.stokes_reason.find("convective term kept"), std::string::npos);
}

TEST(ConfigDerived, VelocityFromPressureDropBodyForceOrDefault) {
  const std::string path = write_case_file("channel.toml", minimal_case);
  // traction 0.5 Pa → 0 Pa across x (ℓ = 10 μm); L = 10 μm (smallest extent)
  const auto pressure_driven = rouleau::derive_quantities(rouleau::load_case(
      path, {"boundary.x_min.type=traction", "boundary.x_min.pressure_Pa=0.5", "boundary.x_max.type=traction"}));
  EXPECT_DOUBLE_EQ(pressure_driven.length_scale, 10.0);
  EXPECT_DOUBLE_EQ(pressure_driven.velocity_scale, 0.5 * 10.0 * 10.0 / (8.0 * 1.2e-3 * 10.0));
  const auto force_driven =
      rouleau::derive_quantities(rouleau::load_case(path, {"fluid.body_force_Pa_um=[0, 0, 0.03]"}));
  EXPECT_DOUBLE_EQ(force_driven.velocity_scale, 0.03 * 10.0 * 10.0 / (8.0 * 1.2e-3));
  const auto at_rest = rouleau::derive_quantities(rouleau::load_case(path));
  EXPECT_DOUBLE_EQ(at_rest.velocity_scale, 1.0);
  const auto given = rouleau::derive_quantities(
      rouleau::load_case(path, {"scales.length_um=2", "scales.velocity_um_s=3", "fluid.body_force_Pa_um=[1,0,0]"}));
  EXPECT_DOUBLE_EQ(given.length_scale, 2.0);
  EXPECT_DOUBLE_EQ(given.velocity_scale, 3.0);
}

TEST(ConfigCells, BuiltInKindsHaveThePaperValues) {
  const CaseConfig config = rouleau::load_case(write_case_file("fluid_only.toml", minimal_case));
  ASSERT_EQ(config.cell_kinds.size(), 3u);
  EXPECT_EQ(config.cell_kinds[0].name, "normal");
  EXPECT_EQ(config.cell_kinds[1].name, "sickle");
  EXPECT_EQ(config.cell_kinds[2].name, "capsule");
  EXPECT_TRUE(config.cells.empty());

  // the paper's membrane: G_s = 4.2e-3 dyn/cm = 4.2 pN/μm, κ = 1.8e-12 dyn·cm = 0.18 pN·μm
  const double dyn_per_cm_in_pN_per_um = 1e-3 / 1e-6;   // [N/m] / [N/m]
  const double dyn_cm_in_pN_um = 1e-7 / 1e-18;          // [J] / [J]
  EXPECT_DOUBLE_EQ(4.2e-3 * dyn_per_cm_in_pN_per_um, rouleau::paper_membrane_shear_modulus);
  EXPECT_DOUBLE_EQ(1.8e-12 * dyn_cm_in_pN_um, rouleau::paper_bending_modulus);
  // h = sqrt(3κ/G_s) = 0.3586 μm, rounded to 0.36 μm
  EXPECT_NEAR(std::sqrt(3.0 * rouleau::paper_bending_modulus / rouleau::paper_membrane_shear_modulus), 0.36, 0.005);

  const CellKindConfig& normal = kind_of(config, "normal");
  EXPECT_EQ(normal.shape, rouleau::CellShape::rbc);
  EXPECT_EQ(normal.body, rouleau::CellBody::shell);
  EXPECT_EQ(normal.resolution, rouleau::MeshResolution::paper);
  EXPECT_DOUBLE_EQ(normal.diameter, 7.82);
  EXPECT_DOUBLE_EQ(normal.shell_thickness, 0.36);
  EXPECT_NEAR(normal.shear_modulus, 11.67, 0.005);  // G = G_s / h [Pa]
  EXPECT_DOUBLE_EQ(normal.shear_modulus, 4.2 / 0.36);
  EXPECT_DOUBLE_EQ(normal.poisson_ratio, 0.45);
  EXPECT_DOUBLE_EQ(normal.bulk_modulus, 2.0 * normal.shear_modulus * 1.45 / (3.0 * 0.1));  // 112.8 Pa
  EXPECT_DOUBLE_EQ(normal.density, 1.1e-9);  // 1100 kg/m³

  const CellKindConfig& sickle = kind_of(config, "sickle");
  EXPECT_EQ(sickle.shape, rouleau::CellShape::sickle);
  EXPECT_EQ(sickle.body, rouleau::CellBody::shell);
  EXPECT_DOUBLE_EQ(sickle.shear_modulus, 10.0 * normal.shear_modulus);
  EXPECT_DOUBLE_EQ(sickle.bulk_modulus, 10.0 * normal.bulk_modulus);  // same ν
  EXPECT_DOUBLE_EQ(sickle.length, 14.0);
  EXPECT_DOUBLE_EQ(sickle.width, 4.2);
  EXPECT_DOUBLE_EQ(sickle.thickness, 3.0);
  EXPECT_DOUBLE_EQ(sickle.arc_radius, 8.0);
  EXPECT_DOUBLE_EQ(sickle.shell_thickness, normal.shell_thickness);
  EXPECT_DOUBLE_EQ(sickle.density, 1.1e-9);

  const CellKindConfig& capsule = kind_of(config, "capsule");
  EXPECT_EQ(capsule.shape, rouleau::CellShape::sphere);
  EXPECT_DOUBLE_EQ(capsule.diameter, 5.64);
  EXPECT_NEAR(M_PI / 6.0 * std::pow(capsule.diameter, 3), 94.1, 0.5);  // the normal RBC's volume [μm³]
  EXPECT_DOUBLE_EQ(capsule.shear_modulus, normal.shear_modulus);
  EXPECT_DOUBLE_EQ(capsule.bulk_modulus, normal.bulk_modulus);

  EXPECT_EQ(rouleau::find_cell_kind(config, "no_such_kind"), nullptr);
  EXPECT_EQ(rouleau::builtin_cell_kinds().size(), 3u);
}

TEST(ConfigCells, PoissonRatioAndBulkModulusAreInverse) {
  for (const double nu : {-0.5, 0.0, 0.3, 0.45, 0.49}) {
    const double bulk = rouleau::bulk_modulus_from_poisson(11.67, nu);
    EXPECT_NEAR(rouleau::poisson_from_bulk_modulus(11.67, bulk), nu, 1e-14) << nu;
  }
  EXPECT_DOUBLE_EQ(rouleau::bulk_modulus_from_poisson(3.0, 0.25), 5.0);  // K = 2·3·1.25 / (3·0.5)
  EXPECT_DOUBLE_EQ(rouleau::bulk_modulus_from_poisson(3.0, 0.0), 2.0);   // K = 2G/3
}

TEST(ConfigCells, ModuliFromEitherKeyOfEachPair) {
  const std::string path = write_case_file(
      "moduli.toml", minimal_case +
                         "[cell_kinds.normal]\nshell_thickness_um = 0.3\nmembrane_shear_modulus_pN_um = 8.4\n"
                         "[cell_kinds.capsule]\nshear_modulus_Pa = 20\nbulk_modulus_Pa = 100\n"
                         "[cell_kinds.sickle]\nshear_modulus_Pa = 50\n"
                         "[cell_kinds.stiff]\npoisson_ratio = 0.3\nbody = \"filled\"\nshear_modulus_Pa = 1000\n");
  const CaseConfig config = rouleau::load_case(path);
  // membrane modulus: G = G_s / h = 8.4 pN/μm / 0.3 μm = 28 Pa; K follows G through ν = 0.45
  const CellKindConfig& normal = kind_of(config, "normal");
  EXPECT_DOUBLE_EQ(normal.shear_modulus, 28.0);
  EXPECT_DOUBLE_EQ(normal.poisson_ratio, 0.45);
  EXPECT_DOUBLE_EQ(normal.bulk_modulus, rouleau::bulk_modulus_from_poisson(28.0, 0.45));
  // K given: ν = (3K − 2G) / (2(3K + G)) is recorded
  const CellKindConfig& capsule = kind_of(config, "capsule");
  EXPECT_DOUBLE_EQ(capsule.bulk_modulus, 100.0);
  EXPECT_DOUBLE_EQ(capsule.poisson_ratio, (300.0 - 40.0) / (2.0 * (300.0 + 20.0)));
  // G changed alone: K recomputed from the kind's ν
  const CellKindConfig& sickle = kind_of(config, "sickle");
  EXPECT_DOUBLE_EQ(sickle.shear_modulus, 50.0);
  EXPECT_DOUBLE_EQ(sickle.bulk_modulus, rouleau::bulk_modulus_from_poisson(50.0, 0.45));
  // an added kind: ν given
  const CellKindConfig& stiff = kind_of(config, "stiff");
  EXPECT_DOUBLE_EQ(stiff.bulk_modulus, 2.0 * 1000.0 * 1.3 / (3.0 * 0.4));
}

TEST(ConfigCells, AddedKindsStartFromTheBuiltInNormalCellAndFollowTheBuiltIns) {
  const std::string path = write_case_file(
      "kinds.toml", minimal_case +
                        "[cell_kinds.normal]\ndiameter_um = 8.0\n"
                        "[cell_kinds.big]\ndiameter_um = 9.5\nresolution = \"fine\"\nmesh_size_um = 0.4\n"
                        "[cell_kinds.arc]\nshape = \"sickle\"\narc_radius_um = 6\ndensity_kg_m3 = 1150\n");
  const CaseConfig config = rouleau::load_case(path);
  ASSERT_EQ(config.cell_kinds.size(), 5u);
  const std::vector<std::string> names{"normal", "sickle", "capsule", "arc", "big"};
  for (std::size_t i = 0; i < names.size(); ++i) EXPECT_EQ(config.cell_kinds[i].name, names[i]);
  EXPECT_DOUBLE_EQ(kind_of(config, "normal").diameter, 8.0);
  const CellKindConfig& big = kind_of(config, "big");
  const CellKindConfig builtin_normal = rouleau::builtin_cell_kinds().front();
  EXPECT_EQ(big.shape, rouleau::CellShape::rbc);
  EXPECT_DOUBLE_EQ(big.diameter, 9.5);
  EXPECT_EQ(big.resolution, rouleau::MeshResolution::fine);
  EXPECT_DOUBLE_EQ(big.mesh_size, 0.4);
  EXPECT_DOUBLE_EQ(big.shear_modulus, builtin_normal.shear_modulus);
  const CellKindConfig& arc = kind_of(config, "arc");
  EXPECT_EQ(arc.shape, rouleau::CellShape::sickle);
  EXPECT_DOUBLE_EQ(arc.arc_radius, 6.0);
  EXPECT_DOUBLE_EQ(arc.density, 1.15e-9);
  EXPECT_DOUBLE_EQ(arc.shear_modulus, builtin_normal.shear_modulus);  // the normal cell's, not the sickle's
}

TEST(ConfigCells, CellsTakeTheirKindCentreAndOrientation) {
  const std::string path = write_case_file(
      "cells.toml", minimal_case + "[cell_kinds.stiff]\nshear_modulus_Pa = 100\n"
                                   "[[cells]]\ncenter_um = [5, 10, 15]\n"
                                   "[[cells]]\nkind = \"stiff\"\ncenter_um = [5, 10, 5.5]\norientation_deg = [0, 90, -45]\n"
                                   "[coupling]\nallow_unstable_step = true\n");
  const CaseConfig config = rouleau::load_case(path);
  ASSERT_EQ(config.cells.size(), 2u);
  EXPECT_EQ(config.cells[0].kind, "normal");
  EXPECT_EQ(config.cells[0].center, (std::array<double, 3>{5, 10, 15}));
  EXPECT_EQ(config.cells[0].orientation, (std::array<double, 3>{0, 0, 0}));
  EXPECT_EQ(config.cells[1].kind, "stiff");
  EXPECT_EQ(config.cells[1].center, (std::array<double, 3>{5, 10, 5.5}));
  EXPECT_EQ(config.cells[1].orientation, (std::array<double, 3>{0, 90, -45}));
}

TEST(ConfigCoupling, StableStepIsViscosityTimesElementOverMembraneModulus) {
  // One capsule (G_s = 4.2 pN/μm) in good_case's fluid: Δt ≤ C μ h_f / G_eff with h_f the
  // smallest element edge and G_eff = (4/3) G_s (the stability map's margin); a step above
  // it loads only when the case allows it.
  const std::vector<std::string> one_capsule{"cells=[{kind=\"capsule\", center_um=[20, 0, 10]}]",
                                             "coupling.stable_step_factor=0.5", "time.dt_s=1e-6"};
  const CaseConfig config = rouleau::load_case(good_case, one_capsule);
  const rouleau::DerivedQuantities derived = rouleau::derive_quantities(config);
  double h_f = 1e300;
  for (int d = 0; d < 3; ++d)
    h_f = std::min(h_f, rouleau::smallest_graded_interval(config.domain.lower[d], config.domain.upper[d],
                                                          config.domain.elements[d], config.domain.wall_grading[d]));
  const CellKindConfig& capsule = kind_of(config, "capsule");
  const double margin = 4.0 / 3.0;
  const double expected =
      0.5 * config.fluid.viscosity * h_f / (margin * capsule.shear_modulus * capsule.shell_thickness);
  std::printf("stable step %.4g s (h_f %.4g um, G_s %.4g pN/um)\n", derived.stable_dt, h_f,
              capsule.shear_modulus * capsule.shell_thickness);
  EXPECT_NEAR(derived.stable_dt, expected, 1e-15 * expected);
  auto with_step = [&](double dt, bool allow) {
    std::vector<std::string> overrides = one_capsule;
    std::ostringstream step;
    step.precision(17);
    step << "time.dt_s=" << dt;
    overrides.push_back(step.str());
    overrides.push_back(std::string("coupling.allow_unstable_step=") + (allow ? "true" : "false"));
    return overrides;
  };
  EXPECT_NO_THROW(rouleau::load_case(good_case, with_step(0.9 * expected, false)));
  EXPECT_EQ(load_error(good_case, with_step(1.1 * expected, false)).key(), "time.dt_s");
  EXPECT_NO_THROW(rouleau::load_case(good_case, with_step(1.1 * expected, true)));
  // strain hardening (C3 = r G) and a global area modulus k_A stiffen it:
  // G_eff = (4/3) [G_s (1 + 30 r) + k_A κ h_f / R], κ = 0.014 for a sphere
  std::vector<std::string> stiffer = one_capsule;
  stiffer.insert(stiffer.end(), {"cell_kinds.capsule.strain_hardening_ratio=0.05",
                                 "cell_kinds.capsule.area_modulus_pN_um=1000"});
  const CaseConfig hardened = rouleau::load_case(good_case, stiffer);
  const double effective = margin * (capsule.shear_modulus * capsule.shell_thickness * (1.0 + 30.0 * 0.05) +
                                    1000.0 * 0.014 * h_f / (0.5 * capsule.diameter));
  EXPECT_NEAR(rouleau::derive_quantities(hardened).stable_dt, 0.5 * config.fluid.viscosity * h_f / effective,
              1e-15 * expected);
  // no cells, or a steady solve: no coupling step to bound
  EXPECT_EQ(rouleau::derive_quantities(rouleau::load_case(good_case)).stable_dt, 0.0);
}

TEST(ConfigCoupling, MorseStiffnessBoundsTheStepOfInteractingCells) {
  // Two capsules with the interaction on: flat faces at the balance gap h* = r0 − ln2/β
  // stiffen as 8π β De h* (p(h) = 2π h φ(h)), a grid-scale modulus G = 8π β De h* h_f²;
  // with De × 10 (twice the paper's two-cell scene's factor) it sets the step, and sickle
  // cells (De × 5 per kind) five times more. One cell alone has no pair to bound.
  const std::vector<std::string> two_capsules{
      "cells=[{kind=\"capsule\", center_um=[20, 0, 10]}, {kind=\"capsule\", center_um=[20, 0, 17]}]",
      "interaction.enabled=true", "interaction.strength_multiplier=10", "time.dt_s=1e-7"};
  const CaseConfig config = rouleau::load_case(good_case, two_capsules);
  double h_f = 1e300;
  for (int d = 0; d < 3; ++d)
    h_f = std::min(h_f, rouleau::smallest_graded_interval(config.domain.lower[d], config.domain.upper[d],
                                                          config.domain.elements[d], config.domain.wall_grading[d]));
  const rouleau::MorseConfig& law = config.interaction.morse;
  const double balance_gap = law.zero_force_length - std::log(2.0) / law.beta;
  const double morse_modulus = 8.0 * M_PI * law.beta * 10.0 * law.well_depth * balance_gap * h_f * h_f;
  const rouleau::DerivedQuantities derived = rouleau::derive_quantities(config);
  std::printf("stable step with Morse x10: %.4g s (G_Morse %.4g pN/um at h_f %.3g um): %s\n", derived.stable_dt,
              morse_modulus, h_f, derived.stable_dt_reason.c_str());
  const double expected = config.coupling.stable_step_factor * config.fluid.viscosity * h_f / morse_modulus;
  EXPECT_NEAR(derived.stable_dt, expected, 1e-14 * expected);
  EXPECT_NE(derived.stable_dt_reason.find("Morse"), std::string::npos);
  std::vector<std::string> sickles = two_capsules;
  sickles[0] = "cells=[{kind=\"sickle\", center_um=[20, 0, 10]}, {kind=\"sickle\", center_um=[20, 0, 17]}]";
  EXPECT_NEAR(rouleau::derive_quantities(rouleau::load_case(good_case, sickles)).stable_dt, expected / 5.0,
              1e-14 * expected);
  std::vector<std::string> interaction_off = two_capsules;
  interaction_off[1] = "interaction.enabled=false";
  const CellKindConfig& capsule = kind_of(config, "capsule");
  const double membrane_step = config.coupling.stable_step_factor * config.fluid.viscosity * h_f /
                               (4.0 / 3.0 * capsule.shear_modulus * capsule.shell_thickness);
  EXPECT_NEAR(rouleau::derive_quantities(rouleau::load_case(good_case, interaction_off)).stable_dt, membrane_step,
              1e-14 * membrane_step);
}

TEST(ConfigCoupling, StrainPerStepBeyondTheMeasuredAccurateRangeIsWarnedOf) {
  // The spheroid in shear: walls ±120 μm/s, 24 μm apart: γ̇ = 10 1/s exactly; at its
  // Δt = 2.5e-3 s a strain of 0.025 per step (no warning), at 1e-2 s 0.1 (a warning that
  // names the step to take, 0.05 / γ̇ = 5e-3 s).
  const std::string cases = std::string(ROULEAU_SOURCE_DIR) + "/cases/";
  const rouleau::DerivedQuantities shear = rouleau::derive_quantities(rouleau::load_case(cases + "spheroid_shear/case.toml"));
  EXPECT_NEAR(shear.shear_rate, 10.0, 1e-12);
  EXPECT_NEAR(shear.strain_per_step, 0.025, 1e-14);
  EXPECT_TRUE(shear.accuracy_warning.empty()) << shear.accuracy_warning;
  const rouleau::DerivedQuantities coarse_step =
      rouleau::derive_quantities(rouleau::load_case(cases + "spheroid_shear/case.toml", {"time.dt_s=1e-2"}));
  EXPECT_NEAR(coarse_step.strain_per_step, 0.1, 1e-14);
  EXPECT_NE(coarse_step.accuracy_warning.find("dt <= 0.005 s"), std::string::npos) << coarse_step.accuracy_warning;
  // --explain says it in the cells' stage: within the range at 2.5e-3 s, beyond it at 1e-2 s.
  const auto cells_stage = [&](const std::vector<std::string>& overrides) {
    const CaseConfig config = rouleau::load_case(cases + "spheroid_shear/case.toml", overrides);
    for (const auto& stage : rouleau::plan_scene(config, rouleau::derive_quantities(config)).stages)
      if (stage.name == "cells") return stage.reason;
    return std::string();
  };
  EXPECT_NE(cells_stage({}).find("strain per step, shear rate x dt = 0.025"), std::string::npos) << cells_stage({});
  EXPECT_NE(cells_stage({}).find("within the 0.05"), std::string::npos);
  EXPECT_NE(cells_stage({"time.dt_s=1e-2"}).find("BEYOND the 0.05"), std::string::npos);
  // The capillary: 10 μm/s in feeders of radius 5 μm, a throat of 2.5 μm: Poiseuille's wall
  // shear rate there 4 V (R/R_t)² / R_t = 64 1/s.
  const rouleau::DerivedQuantities vessel = rouleau::derive_quantities(rouleau::load_case(cases + "capillary/case.toml"));
  EXPECT_NEAR(vessel.shear_rate, 64.0, 1e-12);
  // A closed box at rest (the aggregation scene): no flow to strain the cells, no estimate.
  const rouleau::DerivedQuantities at_rest = rouleau::derive_quantities(rouleau::load_case(cases + "aggregation/case.toml"));
  EXPECT_EQ(at_rest.shear_rate, 0.0);
  EXPECT_TRUE(at_rest.accuracy_warning.empty());
}

TEST(ConfigCells, OverridesReachKindsAndCells) {
  const CaseConfig config = rouleau::load_case(
      good_case, {"cell_kinds.sickle.shear_modulus_Pa=100", "cells=[{kind=\"capsule\", center_um=[20, 0, 10]}]",
                  "time.dt_s=1e-5"});
  EXPECT_DOUBLE_EQ(kind_of(config, "sickle").shear_modulus, 100.0);
  ASSERT_EQ(config.cells.size(), 1u);
  EXPECT_EQ(config.cells[0].kind, "capsule");
  const InputError error = load_error(good_case, {"cell_kinds.normal.poisson_ratio=0.7"});
  EXPECT_EQ(error.file(), "--set");
  EXPECT_EQ(error.key(), "cell_kinds.normal.poisson_ratio");
  const InputError entry_error = load_error(good_case, {"cells=[{center_um=[1, 2, 3]}, {kind=\"nromal\", center_um=[0, 0, 0]}]"});
  EXPECT_EQ(entry_error.file(), "--set");
  EXPECT_EQ(entry_error.key(), "cells[1].kind");
  // The membrane options beyond the paper's law: off in every built-in kind, set per kind.
  for (const CellKindConfig& kind : config.cell_kinds) {
    EXPECT_EQ(kind.strain_hardening_ratio, 0.0) << kind.name;
    EXPECT_EQ(kind.area_modulus, 0.0) << kind.name;
    EXPECT_EQ(kind.volume_modulus, 0.0) << kind.name;
  }
  const CaseConfig mills = rouleau::load_case(
      good_case, {"cell_kinds.normal.strain_hardening_ratio=0.0333", "cell_kinds.normal.area_modulus_pN_um=300"});
  EXPECT_DOUBLE_EQ(kind_of(mills, "normal").strain_hardening_ratio, 0.0333);
  EXPECT_DOUBLE_EQ(kind_of(mills, "normal").area_modulus, 300.0);
  EXPECT_EQ(kind_of(mills, "sickle").area_modulus, 0.0);
  EXPECT_DOUBLE_EQ(rouleau::load_case(good_case, {"cell_kinds.capsule.volume_modulus_Pa=40"})
                       .cell_kinds[2].volume_modulus, 40.0);
  EXPECT_EQ(load_error(good_case, {"cell_kinds.capsule.strain_hardening_ratio=-0.1"}).key(),
            "cell_kinds.capsule.strain_hardening_ratio");
}

TEST(ConfigInteraction, DefaultsGiveTheStatedAdhesionEnergy) {
  // The default De makes flat faces at their balance gap h* = r0 − ln 2/β hold with an
  // adhesion energy −2π ∫_{h*}^{r_c} φ(r) r dr = 0.5 μJ/m² = 0.5 pN/μm (midpoint rule; the
  // unshifted law, as the calibration states it).
  const rouleau::MorseConfig m{};
  const double gap = m.zero_force_length - std::log(2.0) / m.beta;
  const int n = 200000;
  double integral = 0.0;
  for (int k = 0; k < n; ++k) {
    const double r = gap + (k + 0.5) * (m.cutoff - gap) / n;
    const double e = std::exp(m.beta * (m.zero_force_length - r));
    integral += m.well_depth * (e * e - 2.0 * e) * r * (m.cutoff - gap) / n;
  }
  std::printf("adhesion energy of the default Morse law: %.4f pN/um (uJ/m^2)\n", -2.0 * M_PI * integral);
  EXPECT_NEAR(-2.0 * M_PI * integral, 0.5, 0.001);
  const auto kinds = rouleau::builtin_cell_kinds();
  EXPECT_EQ(kinds[0].morse_well_depth_factor, 1.0);
  EXPECT_EQ(kinds[1].morse_well_depth_factor, 5.0);  // sickle: stickier
}

TEST(ConfigResolved, RoundTripGivesAnIdenticalCase) {
  const std::vector<std::vector<std::string>> variants{
      {},
      {"boundary.x_min={type=\"inflow\", mean_speed_um_s=10.1, profile=\"uniform\"}",
       "boundary.x_max={type=\"traction\", pressure_Pa=0.37}", "boundary.z_min.type=wall",
       "boundary.z_max.type=wall", "fluid.density_kg_m3=1099.7", "fluid.viscosity_Pa_s=3.3e-3",
       "case.description=\"quote \\\" and\\nnewline\"", "time.mode=steady", "solver.stokes=off"},
      // cells, a changed and added kinds, each modulus given either way
      {"cell_kinds.normal.diameter_um=7.5", "cell_kinds.normal.shell_thickness_um=0.31",
       "cell_kinds.sickle.membrane_shear_modulus_pN_um=37.1", "cell_kinds.capsule.poisson_ratio=0.49",
       "cell_kinds.capsule.resolution=coarse", "cell_kinds.capsule.density_kg_m3=1093.3",
       "cell_kinds.stiff-1={body=\"filled\", shape=\"sickle\", shear_modulus_Pa=51.3, bulk_modulus_Pa=903.7}",
       "cell_kinds.ball={shape=\"sphere\", diameter_um=4.1, mesh_size_um=0.35, bulk_modulus_Pa=77.7}",
       "cells=[{kind=\"sickle\", center_um=[10.1, 0, 10], orientation_deg=[0, 0, 33.3]},"
       " {center_um=[30, 0.7, 10]}, {kind=\"stiff-1\", center_um=[20, -3, 10]}, {kind=\"ball\", center_um=[3, 2, 3]}]",
       "interaction.enabled=true", "interaction.quadrature=gauss6", "interaction.strength_multiplier=5", "interaction.beta_per_um=3.7",
       "interaction.pair=[{kind_a=\"sickle\", kind_b=\"ball\", well_depth_pN_um3=17.1, cutoff_um=2.2}]",
       "cell_kinds.ball.morse_well_depth_factor=0.3", "cell_kinds.normal.strain_hardening_ratio=0.0333",
       "cell_kinds.normal.area_modulus_pN_um=250.3", "cell_kinds.stiff-1.area_modulus_pN_um=17",
       "cell_kinds.capsule.volume_modulus_Pa=31.5",
       "coupling.support_elements=2.5",
       "coupling.stable_step_factor=0.37", "coupling.allow_unstable_step=true",
       "coupling.gravity_m_s2=[0.1, -9.81, 0.3]", "scene.skip_unneeded_stages=false"},
  };
  for (const auto& overrides : variants) {
    const CaseConfig original = rouleau::load_case(good_case, overrides);
    const std::string text = rouleau::resolved_case_toml(original, rouleau::derive_quantities(original));
    EXPECT_NE(text.find("\n[derived]\n"), std::string::npos);
    EXPECT_NE(text.find("\n[cell_kinds.capsule]\n"), std::string::npos);
    EXPECT_EQ(text.find("\n[[cells]]\n") != std::string::npos, !original.cells.empty());
    const CaseConfig reloaded = rouleau::load_case(write_case_file("resolved.toml", text));
    expect_identical_cases(original, reloaded);
    // and the second generation writes the same text (source_file comment aside)
    const std::string second = rouleau::resolved_case_toml(reloaded, rouleau::derive_quantities(reloaded));
    EXPECT_EQ(text.substr(text.find("[case]")), second.substr(second.find("[case]")));
  }
}

TEST(ConfigResolved, DensityIsWrittenInKilogramsPerCubicMetre) {
  const CaseConfig config = rouleau::load_case(good_case);
  const std::string text = rouleau::resolved_case_toml(config, rouleau::derive_quantities(config));
  EXPECT_NE(text.find("density_kg_m3 = 1025.0\n"), std::string::npos) << text;
  EXPECT_NE(text.find("viscosity_Pa_s = 0.0012\n"), std::string::npos) << text;
}

}  // namespace
