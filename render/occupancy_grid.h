// Empty space of a volume: which parts of its bounds may hold anything a
// ray would see, so that primary rays, shadow rays and the light rays of
// the transmittance grids step over the rest without evaluating the
// graph there.
//
// The bounds are cut into bricks (pbrt-v4 keeps such a majorant grid for
// its media); a brick is empty when the density graph's interval
// enclosure over the brick's box (interp/interval_program.h) says its
// opacity is 0 everywhere in it. Bricks whose enclosure is too loose to
// tell are cut again into 4 x 4 x 4 cells, as Keeter's MPR subdivides its
// tiles, so that the surface of a solid keeps thin occupied shells around
// it and the space away from it is empty in large steps. A brick's cells
// are bounded by octants (2 x 2 x 2 cells, then each cell of an octant
// that cannot tell): where a thin shell crosses a brick, most of its
// octants are empty, and each is one enclosure instead of eight. A box
// whose opacity is certainly above 0 is full, and is not cut: marking a
// cell occupied costs samples, never a pixel.
//
// A sample is skipped only where its opacity is certainly 0, and such a
// sample adds nothing to a ray: skipping changes no pixel.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "graph/diagnostic.h"

namespace shadetree {

// What the box [lo, hi] holds of the volume: certainly nothing visible;
// maybe something; or certainly something visible at every point, when
// its parts are not worth bounding one by one.
enum class BoxContents { empty, some, full };

// The contents of a box. Called from worker threads.
using BoxOccupancy = std::function<BoxContents(const glm::vec3& lo, const glm::vec3& hi)>;

// Where a ray may meet something visible (`from`), and where it leaves the
// occupied cell it meets there (`until`): the ray need not ask again
// before `until`.
struct Clearance {
  float from = 0.0f, until = 0.0f;
};

class OccupancyGrid {
 public:
  static constexpr int bricks_per_side = 16;     // the first level
  static constexpr int cells_per_brick_side = 4;  // the second, where the first cannot tell
  static constexpr int cells_per_side = bricks_per_side * cells_per_brick_side;
  static_assert((cells_per_brick_side & (cells_per_brick_side - 1)) == 0, "a brick's cells are bounded by octants");
  // Occupied cells walked ahead at most when a ray asks from inside one.
  static constexpr int max_occupied_run = 16;

  // The first level, every cell of a brick that is not empty occupied;
  // none when it finds less than `least_empty` of the bounds empty:
  // stepping through the cells would then cost more than the samples it
  // saves (docs/architecture.md has the measurements).
  static Result<std::optional<OccupancyGrid>> build(const glm::vec3& lo, const glm::vec3& hi,
                                                    const BoxOccupancy& occupied, double least_empty, int threads,
                                                    const std::atomic<bool>* cancel);

  // The bricks at even coordinates, one in eight: the first level bounds
  // them first, and the second level may too, to tell whether the rest is
  // worth bounding.
  static bool surveyed(const glm::ivec3& brick) { return brick.x % 2 == 0 && brick.y % 2 == 0 && brick.z % 2 == 0; }

  // The second level: the cells of each brick that is neither empty nor
  // full (of those `surveyed`, or of the others), bounded by octants.
  Status refine(const BoxOccupancy& occupied, bool surveyed, int threads, const std::atomic<bool>* cancel);

  // How many bricks of the survey, or of the others, are not empty.
  long occupied_bricks(bool surveyed) const;
  // The empty share of the surveyed bricks' volume.
  double surveyed_empty_fraction() const;

  // Whether the point may hold something visible; everything outside the
  // bounds may.
  bool occupied(const glm::vec3& point) const;

  // Along the ray origin + t direction from t, the first t where it may
  // meet something visible: where it enters an occupied cell, a little
  // before it to be safe, or `end` if it meets none before.
  Clearance next_occupied(const glm::vec3& origin, const glm::vec3& direction, float t, float end) const;

  double empty_fraction() const;  // of the bounds' volume

  // The grid's states as bytes (a brick a byte, then a cell a bit), and
  // the grid of [lo, hi] those bytes make: none where they are not a
  // grid's (cut short, too long, a brick's state unknown, or an empty
  // brick with an occupied cell).
  std::string serialized() const;
  static constexpr std::size_t serialized_size() {
    return std::size_t{bricks_per_side} * bricks_per_side * bricks_per_side +
           std::size_t{cells_per_side} * cells_per_side * cells_per_side / 8;
  }
  static std::optional<OccupancyGrid> deserialized(const glm::vec3& lo, const glm::vec3& hi, std::string_view bytes);
  std::size_t bytes() const { return cells_.size() + bricks_.size(); }

 private:
  // [lo, hi] with every brick holding some and every cell occupied.
  OccupancyGrid(const glm::vec3& lo, const glm::vec3& hi);
  // The cell of the finest level that a point of the bounds lies in.
  glm::ivec3 cell_of(const glm::vec3& point) const;
  static std::size_t brick_index(const glm::ivec3& brick) {
    return (static_cast<std::size_t>(brick.z) * bricks_per_side + brick.y) * bricks_per_side + brick.x;
  }
  std::uint8_t& brick_state(const glm::ivec3& brick) { return bricks_[brick_index(brick)]; }
  // Every cell of the cube of `side` cells a side from cell `first`.
  void set_cells(const glm::ivec3& first, int side, std::uint8_t state);
  // Bounds the eight octants of the cube of `side` cells from `first`
  // (whose own contents are `some`), and the octants of each octant that
  // holds some in turn, down to single cells: whether any cell may hold
  // something visible.
  bool refine_octants(const BoxOccupancy& occupied, const glm::ivec3& first, int side);
  bool inside(const glm::vec3& point) const;
  bool cell_occupied(const glm::ivec3& cell) const {
    return cells_[(static_cast<std::size_t>(cell.z) * cells_per_side + cell.y) * cells_per_side + cell.x] != 0;
  }
  // Where the ray leaves the box of `cells` cells (along each axis) from
  // `first`, and through a face across which axis (the ray given by its
  // origin and the inverse of its direction).
  struct Exit {
    float t;
    int axis;
  };
  Exit exit_of(const glm::ivec3& first, const glm::ivec3& cells, const glm::vec3& origin,
               const glm::vec3& inverse_direction) const;
  // Sets empty_reach_ from the bricks' states; after every change to them.
  void reach_across_empty_bricks();

  glm::vec3 lo_{0.0f}, hi_{0.0f}, cell_size_{1.0f}, cells_per_unit_{1.0f};
  // What a brick holds (BoxContents), as it is kept.
  static constexpr std::uint8_t empty_brick = 0, some_brick = 1, full_brick = 2;
  std::vector<std::uint8_t> bricks_;  // per brick: empty, some (its cells say where) or full
  std::vector<std::uint8_t> cells_;   // per cell of the finest level: 0 empty, 1 occupied
  // Per brick: 0 where it is not empty, else r >= 1 such that every brick
  // within r - 1 of it along each axis is empty (or past the bounds), up
  // to max_empty_reach. The walk crosses that cube of bricks at once: a
  // ray through the empty space about a small object used to cross it a
  // brick at a time.
  static constexpr int max_empty_reach = 8;
  std::vector<std::uint8_t> empty_reach_;
};

}  // namespace shadetree
