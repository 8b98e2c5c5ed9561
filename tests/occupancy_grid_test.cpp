// The empty space of a volume's bounds: bricks and cells from a box test,
// and rays stepping over the empty ones without passing an occupied one.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <random>
#include <string>

#include <glm/geometric.hpp>

#include "render/occupancy_grid.h"

namespace shadetree {
namespace {

constexpr float radius = 0.5f;

// What a box holds of the ball of `radius` about the origin: an exact box
// test, as tight as an interval bound can be.
BoxContents meets_sphere(const glm::vec3& lo, const glm::vec3& hi) {
  const glm::vec3 nearest = glm::clamp(glm::vec3(0.0f), lo, hi);
  const glm::vec3 farthest = glm::max(glm::abs(lo), glm::abs(hi));
  if (glm::length(nearest) > radius) return BoxContents::empty;
  return glm::length(farthest) <= radius ? BoxContents::full : BoxContents::some;
}

OccupancyGrid sphere_grid(bool refined = true) {
  Result<std::optional<OccupancyGrid>> grid =
      OccupancyGrid::build(glm::vec3(-1.0f), glm::vec3(1.0f), meets_sphere, 0.0, 2, nullptr);
  EXPECT_TRUE(grid.ok() && grid->has_value());
  if (refined)
    for (bool surveyed : {true, false}) EXPECT_TRUE((*grid)->refine(meets_sphere, surveyed, 2, nullptr).ok());
  return std::move(**grid);
}

// The cells that meet the sphere hold about its share of the cube,
// (4/3 pi 0.5^3) / 8 = 6.5%, plus the shell of cells its surface crosses.
TEST(OccupancyGrid, TheSpaceAroundASphereIsEmpty) {
  const OccupancyGrid grid = sphere_grid();
  const double sphere = 4.0 / 3.0 * M_PI * radius * radius * radius / 8.0;
  EXPECT_GT(grid.empty_fraction(), 1.0 - 2.0 * sphere);
  EXPECT_LT(grid.empty_fraction(), 1.0 - sphere);
  EXPECT_TRUE(grid.occupied(glm::vec3(0.0f)));
  EXPECT_TRUE(grid.occupied(glm::vec3(0.49f, 0.0f, 0.0f)));
  EXPECT_FALSE(grid.occupied(glm::vec3(0.9f, 0.9f, 0.9f)));
  EXPECT_TRUE(grid.occupied(glm::vec3(2.0f, 0.0f, 0.0f))) << "outside the bounds nothing is known";
}

// The first level alone holds the sphere in whole bricks: less of the
// cube is empty, and what is empty is a part of the refined grid's.
TEST(OccupancyGrid, TheFirstLevelHoldsTheSphereInWholeBricks) {
  const OccupancyGrid first = sphere_grid(false), refined = sphere_grid();
  EXPECT_LT(first.empty_fraction(), refined.empty_fraction());
  EXPECT_GT(first.empty_fraction(), 0.5);
  std::mt19937 random(3);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  for (int n = 0; n < 10000; ++n) {
    const glm::vec3 point(unit(random), unit(random), unit(random));
    if (refined.occupied(point)) ASSERT_TRUE(first.occupied(point)) << point.x << ", " << point.y << ", " << point.z;
  }
}

// The survey's bricks, one in eight, refined alone: their cells' empty
// share stands for the whole grid's (the sphere is as symmetric about
// the surveyed bricks as about the others), and the other bricks keep
// their first level until they are refined in turn.
TEST(OccupancyGrid, TheSurveyedBricksTellTheSecondLevelsEmptyShare) {
  Result<std::optional<OccupancyGrid>> built =
      OccupancyGrid::build(glm::vec3(-1.0f), glm::vec3(1.0f), meets_sphere, 0.0, 2, nullptr);
  ASSERT_TRUE(built.ok() && built->has_value());
  OccupancyGrid& grid = **built;
  const long surveyed = grid.occupied_bricks(true), others = grid.occupied_bricks(false);
  // The sphere's 8 x 8 x 8 bricks about the centre, less the corners it misses.
  EXPECT_GT(surveyed + others, 400);
  EXPECT_LT(surveyed + others, 512);
  EXPECT_NEAR(static_cast<double>(surveyed) / static_cast<double>(surveyed + others), 1.0 / 8.0, 0.02);
  ASSERT_TRUE(grid.refine(meets_sphere, true, 2, nullptr).ok());
  const OccupancyGrid refined = sphere_grid();
  EXPECT_NEAR(grid.surveyed_empty_fraction(), refined.empty_fraction(), 0.01);
  // Points outside the sphere in bricks its surface crosses: in the
  // brick at (12, 8, 8), a surveyed one, and at (11, 9, 9), which is not.
  const glm::vec3 in_surveyed(0.6f, 0.01f, 0.01f), in_other(0.49f, 0.24f, 0.24f);
  EXPECT_FALSE(grid.occupied(in_surveyed));
  EXPECT_TRUE(grid.occupied(in_other));
  EXPECT_FALSE(refined.occupied(in_other));
}

// The cells of a brick the sphere's surface crosses are bounded by
// octants: each of its eight 2 x 2 x 2 octants once, and the eight cells
// of an octant the surface crosses too, 16 enclosures where it crosses
// one octant instead of 64. Inside the sphere nothing is bounded again: a
// brick or an octant there is full. A box test that finds every box
// inside an empty or full one empty or full alike (the sphere's) then
// marks each cell as bounding it alone would.
TEST(OccupancyGrid, ABricksCellsAreBoundedByOctants) {
  const glm::vec3 lo(-1.0f), hi(1.0f);
  Result<std::optional<OccupancyGrid>> built = OccupancyGrid::build(lo, hi, meets_sphere, 0.0, 2, nullptr);
  ASSERT_TRUE(built.ok() && built->has_value());
  OccupancyGrid& grid = **built;
  constexpr int cells = OccupancyGrid::cells_per_side, brick_side = OccupancyGrid::cells_per_brick_side;
  const glm::vec3 cell_size = (hi - lo) / static_cast<float>(cells);
  auto contents = [&](const glm::ivec3& first, int side) {
    const glm::vec3 box_lo = lo + glm::vec3(first) * cell_size;
    return meets_sphere(box_lo, box_lo + static_cast<float>(side) * cell_size);
  };
  long expected = 0, full_bricks = 0;
  for (int z = 0; z < cells; z += brick_side)
    for (int y = 0; y < cells; y += brick_side)
      for (int x = 0; x < cells; x += brick_side) {
        const glm::ivec3 brick(x, y, z);
        full_bricks += contents(brick, brick_side) == BoxContents::full;
        if (contents(brick, brick_side) != BoxContents::some) continue;
        for (int octant = 0; octant < 8; ++octant) {
          const glm::ivec3 first = brick + (brick_side / 2) * glm::ivec3(octant & 1, (octant >> 1) & 1, octant >> 2);
          expected += contents(first, brick_side / 2) == BoxContents::some ? 9 : 1;
        }
      }
  EXPECT_GT(full_bricks, 100);  // of the sphere's 8 x 8 x 8 bricks about the centre
  std::atomic<long> enclosures = 0;
  const BoxOccupancy counted = [&](const glm::vec3& box_lo, const glm::vec3& box_hi) {
    ++enclosures;
    return meets_sphere(box_lo, box_hi);
  };
  for (bool surveyed : {true, false}) ASSERT_TRUE(grid.refine(counted, surveyed, 2, nullptr).ok());
  EXPECT_EQ(enclosures.load(), expected);
  for (int z = 0; z < cells; ++z)
    for (int y = 0; y < cells; ++y)
      for (int x = 0; x < cells; ++x) {
        const glm::ivec3 cell(x, y, z);
        ASSERT_EQ(grid.occupied(lo + (glm::vec3(cell) + 0.5f) * cell_size), contents(cell, 1) != BoxContents::empty)
            << x << ", " << y << ", " << z;
      }
}

// A ray through the cube stops before the sphere, and never past a point
// of it: walked in small steps, every point before the stop lies outside
// the sphere. A ray that misses the sphere runs to its end.
TEST(OccupancyGrid, RaysStopBeforeTheSphereAndNeverInsideIt) {
  const OccupancyGrid grid = sphere_grid();
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  int hits = 0, misses = 0;
  for (int n = 0; n < 2000; ++n) {
    const glm::vec3 origin(unit(random), unit(random), unit(random));
    glm::vec3 direction(unit(random), unit(random), unit(random));
    if (glm::length(direction) < 0.1f) continue;
    direction = glm::normalize(direction);
    if (glm::length(origin) <= radius) {
      EXPECT_EQ(grid.next_occupied(origin, direction, 0.0f, 4.0f).from, 0.0f) << "a ray that starts in the sphere";
      continue;
    }
    const float stop = grid.next_occupied(origin, direction, 0.0f, 4.0f).from;
    for (float t = 0.0f; t < stop; t += 1e-3f)
      ASSERT_GT(glm::length(origin + t * direction), radius) << "ray " << n << " skipped the sphere at t = " << t;
    // Where the ray meets the sphere (|o + t d| = r), if it does.
    const float b = glm::dot(origin, direction), c = glm::dot(origin, origin) - radius * radius;
    const float discriminant = b * b - c;
    const bool meets = discriminant >= 0.0f && -b - std::sqrt(discriminant) > 0.0f;
    if (meets) {
      ++hits;
      EXPECT_LE(stop, -b - std::sqrt(discriminant));
    } else if (!grid.occupied(origin)) {
      // It steps over empty space, at least out of the cell it starts in.
      ++misses;
      EXPECT_GT(stop, 0.0f);
    }
  }
  EXPECT_GT(hits, 100);
  EXPECT_GT(misses, 100);
}

// Where a ray asks from inside an occupied cell, it is told it need not ask
// again until it leaves the run of occupied cells it is in: every point
// before `until` lies in an occupied cell, and the run reaches past the
// ray's own cell where the shell is thick enough.
TEST(OccupancyGrid, ARayInsideOccupiedCellsIsClearUntilItLeavesThem) {
  const OccupancyGrid grid = sphere_grid();
  std::mt19937 random(11);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  const float cell = 2.0f / OccupancyGrid::cells_per_side;
  int beyond_own_cell = 0, asked = 0;
  for (int n = 0; n < 2000; ++n) {
    const glm::vec3 origin = 0.45f * glm::vec3(unit(random), unit(random), unit(random));
    glm::vec3 direction(unit(random), unit(random), unit(random));
    if (glm::length(direction) < 0.1f || !grid.occupied(origin)) continue;
    direction = glm::normalize(direction);
    const Clearance clear = grid.next_occupied(origin, direction, 0.0f, 4.0f);
    ++asked;
    EXPECT_EQ(clear.from, 0.0f);
    for (float t = 0.0f; t < clear.until; t += 1e-3f)
      ASSERT_TRUE(grid.occupied(origin + t * direction)) << "ray " << n << " left the occupied cells at t = " << t;
    beyond_own_cell += clear.until > 2.0f * cell;
  }
  EXPECT_GT(asked, 500);
  EXPECT_GT(beyond_own_cell, asked / 2) << "the sphere's cells are a run of about 16 across";
}

// An enclosure that knows nothing leaves nothing empty; a grid that would
// find too little empty is not built.
TEST(OccupancyGrid, ABoundThatKnowsNothingSkipsNothing) {
  const BoxOccupancy everywhere = [](const glm::vec3&, const glm::vec3&) { return BoxContents::some; };
  Result<std::optional<OccupancyGrid>> grid =
      OccupancyGrid::build(glm::vec3(0.0f), glm::vec3(1.0f), everywhere, 0.0, 1, nullptr);
  ASSERT_TRUE(grid.ok() && grid->has_value());
  EXPECT_EQ((*grid)->empty_fraction(), 0.0);
  EXPECT_EQ((*grid)->next_occupied(glm::vec3(0.5f), glm::vec3(1.0f, 0.0f, 0.0f), 0.1f, 1.0f).from, 0.1f);
  grid = OccupancyGrid::build(glm::vec3(0.0f), glm::vec3(1.0f), everywhere, 0.5, 1, nullptr);
  ASSERT_TRUE(grid.ok());
  EXPECT_FALSE(grid->has_value());
  // The sphere leaves about 90% of its first level's bricks empty.
  grid = OccupancyGrid::build(glm::vec3(-1.0f), glm::vec3(1.0f), meets_sphere, 0.5, 1, nullptr);
  ASSERT_TRUE(grid.ok());
  EXPECT_TRUE(grid->has_value());
}

TEST(OccupancyGrid, CancellingStopsTheBuild) {
  const std::atomic<bool> cancel{true};
  Result<std::optional<OccupancyGrid>> grid =
      OccupancyGrid::build(glm::vec3(0.0f), glm::vec3(1.0f), meets_sphere, 0.0, 1, &cancel);
  EXPECT_FALSE(grid.ok());
}

// A grid's bytes make the same grid again: every cell, and every ray's
// walk, as the grid it was read from. Bytes that are not a grid's make
// none.
TEST(OccupancyGrid, AGridsBytesMakeTheSameGrid) {
  const OccupancyGrid grid = sphere_grid();
  const std::string bytes = grid.serialized();
  ASSERT_EQ(bytes.size(), OccupancyGrid::serialized_size());
  const std::optional<OccupancyGrid> read = OccupancyGrid::deserialized(glm::vec3(-1.0f), glm::vec3(1.0f), bytes);
  ASSERT_TRUE(read.has_value());
  EXPECT_EQ(read->empty_fraction(), grid.empty_fraction());
  std::mt19937 random(11);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  for (int n = 0; n < 20000; ++n) {
    const glm::vec3 point(unit(random), unit(random), unit(random));
    ASSERT_EQ(read->occupied(point), grid.occupied(point));
    const glm::vec3 direction = glm::normalize(glm::vec3(unit(random), unit(random), unit(random)) + 1e-3f);
    const Clearance expected = grid.next_occupied(point, direction, 0.0f, 4.0f);
    const Clearance found = read->next_occupied(point, direction, 0.0f, 4.0f);
    ASSERT_EQ(found.from, expected.from);
    ASSERT_EQ(found.until, expected.until);
  }
  EXPECT_FALSE(OccupancyGrid::deserialized(glm::vec3(-1.0f), glm::vec3(1.0f), bytes.substr(1)));
  EXPECT_FALSE(OccupancyGrid::deserialized(glm::vec3(-1.0f), glm::vec3(1.0f), bytes + '\0'));
  std::string unknown_state = bytes;
  unknown_state[0] = 3;
  EXPECT_FALSE(OccupancyGrid::deserialized(glm::vec3(-1.0f), glm::vec3(1.0f), unknown_state));
  // The first brick is a corner's, which the sphere leaves empty.
  ASSERT_EQ(bytes[0], 0);
  std::string occupied_in_empty_brick = bytes;
  occupied_in_empty_brick[OccupancyGrid::serialized_size() - OccupancyGrid::cells_per_side *
                                                                  OccupancyGrid::cells_per_side *
                                                                  OccupancyGrid::cells_per_side / 8] = 1;
  EXPECT_FALSE(OccupancyGrid::deserialized(glm::vec3(-1.0f), glm::vec3(1.0f), occupied_in_empty_brick));
}

}  // namespace
}  // namespace shadetree
