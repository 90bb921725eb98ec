// The neighbour search (kernels/point_bins.hpp) and the CSR steps (kernels/csr_rows.hpp)
// against plain serial references: the binned points in (bin, index) order; a search
// visiting every point within the reach exactly once, in periodic and walled boxes, with
// many bins and with fewer bins than the search spans; a search to each bin's own depth
// visiting every point whose support holds the query; the nearest point within a radius
// as by a search of every point; row counts to offsets and the gathering of marked indices
// as by serial loops; the boxes within a gap as by a test of every pair.
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "geometry/box_overlaps.hpp"
#include "kernels/csr_rows.hpp"
#include "kernels/point_bins.hpp"

namespace rouleau {
namespace {

using ExecSpace = Kokkos::DefaultExecutionSpace;
using Positions = Kokkos::View<double* [3]>;

Positions random_positions(const int count, const double lower[3], const double upper[3], const double spill,
                           const unsigned seed) {
  std::mt19937 generator(seed);
  Positions positions("positions", count);
  auto host = Kokkos::create_mirror_view(positions);
  for (int p = 0; p < count; ++p)
    for (int d = 0; d < 3; ++d)
      host(p, d) = std::uniform_real_distribution<double>(lower[d] - spill, upper[d] + spill)(generator);
  Kokkos::deep_copy(positions, host);
  return positions;
}

// The points each query's search visits, in visiting order (at most max_visits): to the
// grid's reach, or to each bin's depth when `depth` is given.
struct VisitRecorder {
  BinnedPoints<> binned;
  Kokkos::View<int* [3]> depth;
  Positions queries;
  Kokkos::View<int**> seen;
  Kokkos::View<int*> count;
  int max_visits;
  KOKKOS_INLINE_FUNCTION void operator()(const int q) const {
    const double x[3] = {queries(q, 0), queries(q, 1), queries(q, 2)};
    int k = 0;
    auto record = [&](const int p) {
      if (k < max_visits) seen(q, k) = p;
      ++k;
    };
    if (depth.extent(0) > 0)
      binned.for_each_point_reaching(x, depth, record);
    else
      binned.for_each_point_near(x, record);
    count(q) = k;
  }
};

std::vector<std::vector<int>> visits(const BinnedPoints<>& binned, const Positions& queries, const int max_visits,
                                     const Kokkos::View<int* [3]>& depth = {}) {
  const int n = static_cast<int>(queries.extent(0));
  const VisitRecorder recorder{binned, depth, queries, Kokkos::View<int**>("seen", n, max_visits),
                               Kokkos::View<int*>("count", n), max_visits};
  Kokkos::parallel_for("visits", Kokkos::RangePolicy<ExecSpace>(0, n), recorder);
  auto host_seen = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), recorder.seen);
  auto host_count = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), recorder.count);
  std::vector<std::vector<int>> result(n);
  for (int q = 0; q < n; ++q)
    for (int k = 0; k < std::min(host_count(q), max_visits); ++k) result[q].push_back(host_seen(q, k));
  for (int q = 0; q < n; ++q) EXPECT_LE(host_count(q), max_visits);
  return result;
}

// The points of a test: every third is left out.
struct AllButEveryThird {
  KOKKOS_INLINE_FUNCTION bool operator()(const int p) const { return p % 3 != 0; }
};

// The rows whose count is 0 or 7.
struct CountIsZeroOrSeven {
  Kokkos::View<int*> counts;
  KOKKOS_INLINE_FUNCTION bool operator()(const int i) const { return counts(i) == 0 || counts(i) == 7; }
};

// For grids with many bins and with fewer bins than 2 reach + 1, periodic and walled: the
// sorted bins hold each included point once, in its bin, in ascending order; a search
// visits each point at most once, and every included point within the reach's distance
// (the bin width times reach, minimum image where periodic) is among those visited.
TEST(PointBins, SearchVisitsEveryNearPointOnceAndBinsAreSorted) {
  const double lower[3] = {-3, 0, 1}, upper[3] = {5, 4, 7};
  struct Case {
    const char* name;
    bool periodic[3];
    double width;
    int reach;
    bool tiling;
  };
  const Case cases[] = {{"tiling, periodic x and z, reach 1", {true, false, true}, 0.9, 1, true},
                        {"tiling, periodic, fewer bins than the search spans", {true, true, true}, 2.5, 1, true},
                        {"cubes, walled, reach 2", {false, false, false}, 0.45, 2, false},
                        {"cubes, walled, one bin across", {false, false, false}, 20.0, 2, false}};
  const int n_points = 700, n_queries = 500;
  const Positions points = random_positions(n_points, lower, upper, 0.0, 5);
  const Positions queries = random_positions(n_queries, lower, upper, 1.0, 6);
  auto host_points = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points);
  auto host_queries = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), queries);
  for (const Case& c : cases) {
    BinnedPoints<> binned;
    const double widths[3] = {c.width, c.width, c.width};
    binned.grid = c.tiling ? bins_tiling(lower, upper, c.periodic, widths, c.reach)
                           : cubic_bins_covering(lower, upper, c.width, c.reach);
    const BinGrid& grid = binned.grid;
    const int included = sort_into_bins<ExecSpace>(points, n_points, AllButEveryThird(), binned);
    auto offsets = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), binned.bin_offsets);
    auto sorted = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), binned.points);
    EXPECT_EQ(included, n_points - (n_points + 2) / 3) << c.name;
    EXPECT_EQ(offsets(grid.num_bins()), included) << c.name;
    int misplaced = 0;
    for (int b = 0; b < grid.num_bins(); ++b)
      for (int k = offsets(b); k < offsets(b + 1); ++k) {
        const int p = sorted(k);
        const double x[3] = {host_points(p, 0), host_points(p, 1), host_points(p, 2)};
        misplaced += grid.bin_of(x) != b || p % 3 == 0 || (k > offsets(b) && sorted(k - 1) >= p);
      }
    EXPECT_EQ(misplaced, 0) << c.name;

    const auto seen = visits(binned, queries, n_points);
    int repeated = 0, missed = 0, near_total = 0;
    for (int q = 0; q < n_queries; ++q) {
      std::vector<int> visited = seen[q];
      std::sort(visited.begin(), visited.end());
      repeated += std::adjacent_find(visited.begin(), visited.end()) != visited.end();
      for (int p = 0; p < n_points; ++p) {
        if (p % 3 == 0) continue;
        double d2 = 0.0;
        for (int d = 0; d < 3; ++d) {
          const double offset = grid.offset(host_points(p, d), host_queries(q, d), d);
          d2 += offset * offset;
        }
        // The bins within the reach hold every point closer than reach × the narrowest
        // bin, for a query inside the box (walled directions clamp the queries outside).
        bool inside = true;
        for (int d = 0; d < 3; ++d)
          inside = inside && (grid.periodic[d] || (host_queries(q, d) >= lower[d] && host_queries(q, d) <= upper[d]));
        const double reach = grid.reach * std::min({grid.width[0], grid.width[1], grid.width[2]});
        if (!inside || d2 >= reach * reach) continue;
        ++near_total;
        missed += !std::binary_search(visited.begin(), visited.end(), p);
      }
    }
    std::printf("  %s: %d bins, %d near pairs, %d missed, %d queries with a repeated point\n", c.name,
                grid.num_bins(), near_total, missed, repeated);
    EXPECT_GT(near_total, n_queries) << c.name;  // the test sees near points
    EXPECT_EQ(missed, 0) << c.name;
    EXPECT_EQ(repeated, 0) << c.name;
  }
}

// 3000 points with supports of their own, 0.2 to 3 μm along each direction, in bins 0.4 μm wide
// searched to each bin's depth (search_depths_covering), periodic and walled: a search from
// any query (inside the box, and outside a walled side) visits every point p whose support
// box |x_d − x_pd| < a_pd holds the query, none twice; and on points whose supports are
// small but for a few, it visits several times fewer points than bins as wide as the largest
// support searched one deep.
TEST(PointBins, SearchToEachBinsDepthVisitsEveryPointWhoseSupportHoldsTheQuery) {
  const double lower[3] = {0, 0, 0}, upper[3] = {20, 12, 16};
  const int n_points = 3000, n_queries = 500;
  const Positions points = random_positions(n_points, lower, upper, 0.0, 5);
  const Positions queries = random_positions(n_queries, lower, upper, 1.0, 6);
  auto host_points = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points);
  auto host_queries = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), queries);
  std::mt19937 generator(7);
  // One point in 50 has a support of 2-3 μm, the others 0.2-0.5 μm.
  Kokkos::View<double* [3], Kokkos::HostSpace> support("support", n_points);
  for (int p = 0; p < n_points; ++p)
    for (int d = 0; d < 3; ++d)
      support(p, d) = p % 50 == 0 ? std::uniform_real_distribution<double>(2.0, 3.0)(generator)
                                  : std::uniform_real_distribution<double>(0.2, 0.5)(generator);
  for (const bool periodic_box : {true, false}) {
    const bool periodic[3] = {periodic_box, false, periodic_box};
    const char* name = periodic_box ? "periodic x and z" : "walled";
    BinnedPoints<> binned;
    const double widths[3] = {0.4, 0.4, 0.4};
    binned.grid = bins_tiling(lower, upper, periodic, widths, 1);
    sort_into_bins<ExecSpace>(points, n_points, EveryPoint(), binned);
    const auto depth = search_depths_covering(binned, support);
    const auto seen = visits(binned, queries, n_points, depth);
    int repeated = 0, missed = 0, held = 0;
    long visited_total = 0;
    for (int q = 0; q < n_queries; ++q) {
      std::vector<int> visited = seen[q];
      visited_total += static_cast<long>(visited.size());
      std::sort(visited.begin(), visited.end());
      repeated += std::adjacent_find(visited.begin(), visited.end()) != visited.end();
      for (int p = 0; p < n_points; ++p) {
        bool holds = true;
        for (int d = 0; d < 3; ++d) {
          double offset = host_queries(q, d) - host_points(p, d);
          if (periodic[d]) offset -= (upper[d] - lower[d]) * std::round(offset / (upper[d] - lower[d]));
          holds = holds && std::fabs(offset) < support(p, d);
        }
        if (!holds) continue;
        ++held;
        missed += !std::binary_search(visited.begin(), visited.end(), p);
      }
    }
    // The same points in bins as wide as the largest support (3 μm), searched one deep.
    BinnedPoints<> wide;
    const double wide_widths[3] = {3.0, 3.0, 3.0};
    wide.grid = bins_tiling(lower, upper, periodic, wide_widths, 1);
    sort_into_bins<ExecSpace>(points, n_points, EveryPoint(), wide);
    long wide_total = 0;
    for (const auto& v : visits(wide, queries, n_points)) wide_total += static_cast<long>(v.size());
    std::printf("  %s: %d (query, support) pairs, %d missed, %d queries with a repeated point; %ld points "
                "visited against %ld with bins as wide as the largest support\n",
                name, held, missed, repeated, visited_total, wide_total);
    EXPECT_GT(held, n_queries) << name;  // the test sees supports holding queries
    EXPECT_EQ(missed, 0) << name;
    EXPECT_EQ(repeated, 0) << name;
    EXPECT_LT(3 * visited_total, wide_total) << name;
  }
}

// 500 random points in a box periodic along x and z, 2000 queries inside, near and outside
// it (and beyond a periodic side): the binned search gives the nearest distance of a
// search of every point (minimum image where periodic), or +∞ beyond the radius.
TEST(PointBins, NearestDistanceWithinTheRadiusMatchesASearchOfEveryPoint) {
  const double lower[3] = {-3, 0, 1}, upper[3] = {5, 4, 7};
  const bool periodic[3] = {true, false, true};
  const double radius = 0.9, widths[3] = {radius, radius, radius};
  std::mt19937 generator(11);
  auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(generator); };
  Kokkos::View<double* [3], Kokkos::HostSpace> points("points", 500);
  for (int p = 0; p < 500; ++p)
    for (int d = 0; d < 3; ++d) points(p, d) = uniform(lower[d], upper[d]);
  BinnedPoints<Kokkos::HostSpace> binned;
  binned.grid = bins_tiling(lower, upper, periodic, widths, 1);
  sort_into_bins<Kokkos::DefaultHostExecutionSpace>(points, 500, EveryPoint(), binned);
  int mismatches = 0, within = 0;
  for (int q = 0; q < 2000; ++q) {
    double x[3];
    for (int d = 0; d < 3; ++d) x[d] = uniform(lower[d] - 2.0, upper[d] + 2.0);
    double nearest = std::numeric_limits<double>::infinity();
    for (int p = 0; p < 500; ++p) {
      double d2 = 0.0;
      for (int d = 0; d < 3; ++d) {
        double offset = x[d] - points(p, d);
        if (periodic[d]) offset -= (upper[d] - lower[d]) * std::round(offset / (upper[d] - lower[d]));
        d2 += offset * offset;
      }
      nearest = std::min(nearest, std::sqrt(d2));
    }
    const double expected = nearest <= radius ? nearest : std::numeric_limits<double>::infinity();
    const double found = nearest_distance(binned, points, x, radius);
    mismatches += !(found == expected || std::fabs(found - expected) <= 1e-14);
    within += std::isfinite(expected);
  }
  std::printf("  %d of 2000 queries have a point within the radius; %d mismatches\n", within, mismatches);
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(within, 500);  // the test sees both answers
  EXPECT_LT(within, 1999);
  const double no_width[3] = {0.0, 1.0, 1.0};
  EXPECT_THROW(bins_tiling(lower, upper, periodic, no_width, 1), std::invalid_argument);
}

// The broad phase: for 400 random boxes (every tenth empty) and gaps 0 and 0.7 μm, the sweep
// and prune finds the pairs a test of every pair finds, in ascending order.
TEST(BoxOverlaps, PairsWithinTheGapAreThoseOfATestOfEveryPair) {
  std::mt19937 generator(8);
  auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(generator); };
  std::vector<Box> boxes(400);
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (int d = 0; d < 3; ++d) {
      const double lower = uniform(0.0, 30.0), size = uniform(0.0, 6.0);
      boxes[i][d] = i % 10 == 0 ? 1e300 : lower;
      boxes[i][3 + d] = i % 10 == 0 ? -1e300 : lower + size;
    }
  boxes[1] = boxes[2];  // two equal boxes: lower x tied
  for (const double gap : {0.0, 0.7}) {
    std::vector<std::pair<int, int>> expected;
    for (int i = 0; i < 400; ++i)
      for (int j = i + 1; j < 400; ++j) {
        bool meet = true;
        for (int d = 0; d < 3; ++d)
          meet = meet && boxes[j][d] <= boxes[i][3 + d] + gap && boxes[i][d] <= boxes[j][3 + d] + gap;
        if (meet) expected.emplace_back(i, j);
      }
    const auto found = boxes_within(boxes, gap);
    std::printf("  gap %.1f: %zu pairs of %zu expected\n", gap, found.size(), expected.size());
    EXPECT_GT(expected.size(), 100u);
    EXPECT_EQ(found, expected);
  }
}

// counts_to_offsets and gather_marked against serial loops, on 10,007 random rows.
TEST(CsrRows, OffsetsAndGatheredIndicesMatchSerialLoops) {
  const int rows = 10007;
  std::mt19937 generator(3);
  std::vector<int> counts(rows);
  for (int& c : counts) c = std::uniform_int_distribution<int>(0, 9)(generator);
  Kokkos::View<int*> offsets("offsets", rows + 1);
  auto host = Kokkos::create_mirror_view(offsets);
  for (int i = 0; i < rows; ++i) host(i) = counts[i];
  host(rows) = -12345;  // ignored
  Kokkos::deep_copy(offsets, host);
  const int total = counts_to_offsets<ExecSpace>("offsets", offsets, rows);
  Kokkos::deep_copy(host, offsets);
  int sum = 0, wrong = 0;
  for (int i = 0; i <= rows; ++i) {
    wrong += host(i) != sum;
    if (i < rows) sum += counts[i];
  }
  EXPECT_EQ(total, sum);
  EXPECT_EQ(wrong, 0);

  // The rows with a count of 0 or 7, gathered twice into one buffer (the second time into
  // a buffer already long enough).
  Kokkos::View<int*> marked_counts("counts", rows), buffer;
  auto host_counts = Kokkos::create_mirror_view(marked_counts);
  for (int i = 0; i < rows; ++i) host_counts(i) = counts[i];
  Kokkos::deep_copy(marked_counts, host_counts);
  std::vector<int> expected;
  for (int i = 0; i < rows; ++i)
    if (counts[i] == 0 || counts[i] == 7) expected.push_back(i);
  for (int repeat = 0; repeat < 2; ++repeat) {
    const auto gathered = gather_marked<ExecSpace>("gather", rows, CountIsZeroOrSeven{marked_counts}, buffer);
    auto host_gathered = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), gathered);
    ASSERT_EQ(host_gathered.extent(0), expected.size());
    EXPECT_TRUE(std::equal(expected.begin(), expected.end(), host_gathered.data()));
  }
}

}  // namespace
}  // namespace rouleau
