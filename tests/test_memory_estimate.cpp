// The memory estimate counts what the code builds: the fluid mesh's nodes and elements,
// the Jacobian's 4x4 blocks and ILU(0)'s widest level, compared with the mesh, the graph
// and the factorization the solver makes for the same case; and it refuses what cannot
// fit or cannot be indexed. A vessel's estimate against the mesh Gmsh makes:
// test_vessel_mesh.cpp (Gmsh stays out of the sanitized unit tests); against measured peak memory: bench/memory_estimate.py.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "config/load_case.hpp"
#include "config/memory_estimate.hpp"
#include "fluid/fluid_matrix.hpp"
#include "run/simulation.hpp"
#include "solver/ilu0_preconditioner.hpp"
#include "temporary_folder.hpp"
#include "util/errors.hpp"

namespace {

const std::string cases_dir = std::string(ROULEAU_SOURCE_DIR) + "/cases";

TEST(MemoryEstimate, CountsTheMeshTheJacobianAndTheIluLevelsAsTheCodeBuildsThem) {
  // A shear box (periodic in x and z), a channel (walls in y, traction in x, periodic in z:
  // closed in x and y, where ILU(0)'s levels are widest) and a box of walls, at sizes
  // where the solver's own structures are quick to build.
  const std::string cache = rouleau::testing::fresh_temporary_folder("memory_estimate_cache").string();
  struct Box {
    std::string case_name, elements;
  };
  for (const Box& box : {Box{"shear_flow", "[6,5,4]"}, Box{"channel", "[7,6,3]"}, Box{"channel", "[5,9,4]"}}) {
    SCOPED_TRACE(box.case_name + " " + box.elements);
    const rouleau::CaseConfig config =
        rouleau::load_case(cases_dir + "/" + box.case_name + "/case.toml", {"domain.elements=" + box.elements});
    const rouleau::MemoryEstimate estimate = rouleau::estimate_memory(config, 2);
    const rouleau::FluidMesh mesh = rouleau::make_case_mesh(config, cache);
    EXPECT_EQ(estimate.fluid_nodes, mesh.num_dof_nodes);
    EXPECT_EQ(estimate.fluid_elements, mesh.num_elements);
    const rouleau::BlockMatrixGraph graph = rouleau::build_fluid_matrix_graph(mesh);
    EXPECT_EQ(estimate.jacobian_blocks, static_cast<double>(graph.node_neighbors.extent(0)));
    const rouleau::Ilu0Preconditioner ilu(graph.row_map, graph.entries);
    // Closed in x and y the count is exact; a periodic x or y makes it about half the node
    // planes along z. (The 4 unknowns of a node sit on 4 levels: a level has as many rows
    // as nodes.)
    const double widest_rows = ilu.widest_level();
    if (box.case_name == "channel")
      EXPECT_EQ(estimate.widest_ilu_level, widest_rows);
    else
      EXPECT_NEAR(estimate.widest_ilu_level, widest_rows, 0.3 * widest_rows);
    std::printf("%s %s: %lld nodes, %.0f blocks, widest ILU(0) level %.0f rows (estimate %.0f)\n",
                box.case_name.c_str(), box.elements.c_str(), estimate.fluid_nodes, estimate.jacobian_blocks,
                widest_rows, estimate.widest_ilu_level);
  }
}

TEST(MemoryEstimate, RefusesWhatDoesNotFitAndWhatTheIndicesCannotHold) {
  const rouleau::CaseConfig small = rouleau::load_case(cases_dir + "/shear_flow/case.toml");
  const rouleau::MemoryEstimate small_estimate = rouleau::estimate_memory(small, 2);
  // The terms come largest first and add up; a small case fits in a gigabyte.
  ASSERT_FALSE(small_estimate.terms.empty());
  double sum = 0.0;
  for (std::size_t i = 0; i < small_estimate.terms.size(); ++i) {
    sum += small_estimate.terms[i].second;
    if (i > 0) EXPECT_LE(small_estimate.terms[i].second, small_estimate.terms[i - 1].second);
  }
  EXPECT_DOUBLE_EQ(sum, small_estimate.total_bytes);
  EXPECT_NO_THROW(rouleau::require_memory(small, small_estimate, 1e9, true));
  // More than is available: refused, naming the key, the estimate and the way out; allowed
  // when the user says so, or when the available memory is unknown.
  try {
    rouleau::require_memory(small, small_estimate, 0.5 * small_estimate.total_bytes, true);
    ADD_FAILURE() << "not refused";
  } catch (const rouleau::InputError& error) {
    EXPECT_EQ(error.key(), "domain.elements");
    EXPECT_NE(error.reason().find("needs about " + rouleau::format_bytes(small_estimate.total_bytes)), std::string::npos)
        << error.reason();
    EXPECT_NE(error.reason().find("--no-memory-check"), std::string::npos) << error.reason();
  }
  EXPECT_NO_THROW(rouleau::require_memory(small, small_estimate, 0.5 * small_estimate.total_bytes, false));
  EXPECT_NO_THROW(rouleau::require_memory(small, small_estimate, -1.0, true));
  // 4096³ elements (inside the range of each component): the Jacobian's blocks overflow a
  // 32-bit index, refused even with --no-memory-check.
  const rouleau::CaseConfig huge =
      rouleau::load_case(cases_dir + "/shear_flow/case.toml", {"domain.elements=[4096,4096,4096]"});
  const rouleau::MemoryEstimate huge_estimate = rouleau::estimate_memory(huge, 2);
  EXPECT_GT(huge_estimate.largest_index_count, 2147483647.0);
  EXPECT_THROW(rouleau::require_memory(huge, huge_estimate, 1e30, false), rouleau::InputError);
}

TEST(MemoryEstimate, BytesAreWrittenInBinaryUnits) {
  EXPECT_EQ(rouleau::format_bytes(512.0), "512 B");
  EXPECT_EQ(rouleau::format_bytes(1536.0), "1.50 KiB");
  EXPECT_EQ(rouleau::format_bytes(300.0 * 1024 * 1024), "300 MiB");
  EXPECT_EQ(rouleau::format_bytes(24072072024.0), "22.4 GiB");  // the 1001³ box's coordinates
}

}  // namespace
