#include "render/occupancy_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>

#include "schedule/image_tiles.h"

namespace shadetree {

namespace {

// Each brick of the grid, one per tile of a bricks_per_side x
// bricks_per_side^2 image, on the worker threads.
Status for_each_brick(int threads, const std::atomic<bool>* cancel, const std::function<void(const glm::ivec3&)>& visit) {
  constexpr int side = OccupancyGrid::bricks_per_side;
  return for_each_tile(
      side, side * side, 1, threads,
      [&](const Tile& tile) -> long {
        visit(glm::ivec3(tile.x0, tile.y0 % side, tile.y0 / side));
        return 1;
      },
      {}, cancel);
}

}  // namespace

OccupancyGrid::OccupancyGrid(const glm::vec3& lo, const glm::vec3& hi)
    : lo_(lo),
      hi_(hi),
      cell_size_((hi - lo) / static_cast<float>(cells_per_side)),
      cells_per_unit_(1.0f / cell_size_),
      bricks_(static_cast<std::size_t>(bricks_per_side) * bricks_per_side * bricks_per_side, some_brick),
      cells_(static_cast<std::size_t>(cells_per_side) * cells_per_side * cells_per_side, 1),
      empty_reach_(bricks_.size(), 0) {}

void OccupancyGrid::reach_across_empty_bricks() {
  // Erosion by a cube of 3 bricks a side, an axis at a time (past the
  // bounds counts as empty): a brick that survives k erosions has every
  // brick within k of it empty.
  constexpr int side = bricks_per_side;
  std::vector<std::uint8_t> within(bricks_.size()), eroded(bricks_.size());
  for (std::size_t b = 0; b < bricks_.size(); ++b) {
    within[b] = bricks_[b] == empty_brick;
    empty_reach_[b] = within[b];
  }
  for (int reach = 2; reach <= max_empty_reach; ++reach) {
    for (int axis = 0; axis < 3; ++axis) {
      const std::size_t stride = axis == 0 ? 1 : axis == 1 ? side : std::size_t{side} * side;
      for (std::size_t b = 0; b < bricks_.size(); ++b) {
        const int at = static_cast<int>(b / stride % side);
        eroded[b] = within[b] && (at == 0 || within[b - stride]) && (at == side - 1 || within[b + stride]);
      }
      within.swap(eroded);
    }
    bool any = false;
    for (std::size_t b = 0; b < bricks_.size(); ++b) {
      empty_reach_[b] = static_cast<std::uint8_t>(empty_reach_[b] + within[b]);
      any = any || within[b];
    }
    if (!any) break;
  }
}

void OccupancyGrid::set_cells(const glm::ivec3& first, int side, std::uint8_t state) {
  for (int k = 0; k < side; ++k)
    for (int j = 0; j < side; ++j)
      for (int i = 0; i < side; ++i) {
        const glm::ivec3 cell = first + glm::ivec3(i, j, k);
        cells_[(static_cast<std::size_t>(cell.z) * cells_per_side + cell.y) * cells_per_side + cell.x] = state;
      }
}

bool OccupancyGrid::refine_octants(const BoxOccupancy& occupied, const glm::ivec3& first, int side) {
  const int half = side / 2;
  bool any = false;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        const glm::ivec3 octant = first + half * glm::ivec3(i, j, k);
        const glm::vec3 octant_lo = lo_ + glm::vec3(octant) * cell_size_;
        const BoxContents contents = occupied(octant_lo, octant_lo + static_cast<float>(half) * cell_size_);
        if (contents == BoxContents::some && half > 1)
          any = refine_octants(occupied, octant, half) || any;
        else
          set_cells(octant, half, contents != BoxContents::empty);
        any = any || contents != BoxContents::empty;
      }
  return any;
}

Result<std::optional<OccupancyGrid>> OccupancyGrid::build(const glm::vec3& lo, const glm::vec3& hi,
                                                          const BoxOccupancy& occupied, double least_empty,
                                                          int threads, const std::atomic<bool>* cancel) {
  OccupancyGrid grid(lo, hi);
  const glm::vec3 brick_size = grid.cell_size_ * static_cast<float>(cells_per_brick_side);
  const auto classify = [&](const glm::ivec3& brick) {
    const glm::vec3 brick_lo = lo + glm::vec3(brick) * brick_size;
    const BoxContents contents = occupied(brick_lo, brick_lo + brick_size);
    if (contents == BoxContents::full) grid.brick_state(brick) = full_brick;
    if (contents != BoxContents::empty) return;
    grid.brick_state(brick) = empty_brick;
    grid.set_cells(brick * cells_per_brick_side, cells_per_brick_side, 0);
  };
  // First a survey of one brick in eight: where it finds far less empty
  // space than is needed, the rest are not bounded (the fireball, which
  // fills its bounds, paid 20 ms for the whole first level to learn that).
  // Only the time taken depends on it.
  Status survey = for_each_brick(threads, cancel, [&](const glm::ivec3& brick) {
    if (surveyed(brick)) classify(brick);
  });
  if (!survey) return survey.error();
  long surveyed_empty = 0;
  for (int z = 0; z < bricks_per_side; z += 2)
    for (int y = 0; y < bricks_per_side; y += 2)
      for (int x = 0; x < bricks_per_side; x += 2) surveyed_empty += grid.brick_state({x, y, z}) == empty_brick;
  // On the gallery's 21 volumes the survey's empty fraction was within 1%
  // of the whole level's.
  constexpr double survey_margin = 0.03;
  if (static_cast<double>(surveyed_empty) < (least_empty - survey_margin) * (grid.bricks_.size() / 8))
    return std::optional<OccupancyGrid>();
  Status first = for_each_brick(threads, cancel, [&](const glm::ivec3& brick) {
    if (!surveyed(brick)) classify(brick);
  });
  if (!first) return first.error();
  const auto empty = static_cast<double>(std::count(grid.bricks_.begin(), grid.bricks_.end(), empty_brick));
  if (empty < least_empty * static_cast<double>(grid.bricks_.size())) return std::optional<OccupancyGrid>();
  grid.reach_across_empty_bricks();
  return std::optional<OccupancyGrid>(std::move(grid));
}

Status OccupancyGrid::refine(const BoxOccupancy& occupied, bool surveyed_bricks, int threads,
                             const std::atomic<bool>* cancel) {
  Status refined = for_each_brick(threads, cancel, [&](const glm::ivec3& brick) {
    std::uint8_t& state = brick_state(brick);
    if (state != some_brick || surveyed(brick) != surveyed_bricks) return;
    state = refine_octants(occupied, brick * cells_per_brick_side, cells_per_brick_side) ? some_brick : empty_brick;
  });
  reach_across_empty_bricks();
  return refined;
}

glm::ivec3 OccupancyGrid::cell_of(const glm::vec3& point) const {
  const glm::ivec3 cell((point - lo_) * cells_per_unit_);  // truncated: the point is inside
  return glm::min(cell, glm::ivec3(cells_per_side - 1));
}

bool OccupancyGrid::inside(const glm::vec3& point) const {
  return point.x >= lo_.x && point.y >= lo_.y && point.z >= lo_.z && point.x <= hi_.x && point.y <= hi_.y &&
         point.z <= hi_.z;
}

bool OccupancyGrid::occupied(const glm::vec3& point) const { return !inside(point) || cell_occupied(cell_of(point)); }

OccupancyGrid::Exit OccupancyGrid::exit_of(const glm::ivec3& first, const glm::ivec3& cells, const glm::vec3& origin,
                                            const glm::vec3& inverse_direction) const {
  Exit exit{std::numeric_limits<float>::infinity(), 0};
  for (int a = 0; a < 3; ++a) {
    if (std::isinf(inverse_direction[a])) continue;  // the ray runs along the faces across this axis
    const int face = first[a] + (inverse_direction[a] > 0.0f ? cells[a] : 0);
    const float at = (lo_[a] + static_cast<float>(face) * cell_size_[a] - origin[a]) * inverse_direction[a];
    if (at < exit.t) exit = {at, a};
  }
  return exit;
}

Clearance OccupancyGrid::next_occupied(const glm::vec3& origin, const glm::vec3& direction, float t,
                                       float end) const {
  // An occupied cell is entered a little before its boundary, and left a
  // little before its far one: rounding in the caller's origin + t
  // direction can move a sample by far less than that.
  const float margin = 1e-3f * std::min({cell_size_.x, cell_size_.y, cell_size_.z});
  const float start = t;
  const glm::vec3 point = origin + t * direction;
  if (!inside(point)) return {t, t};  // outside the bounds nothing is known
  glm::ivec3 cell = cell_of(point);
  // A 3D DDA from cell to cell (Amanatides & Woo 1987), over whole bricks
  // where a brick is empty. The next cell is the current one's (or
  // brick's) neighbour across the face the ray leaves by, stepped as an
  // index: a position a hair past the face could round back into the box
  // when the ray grazes it.
  const glm::ivec3 step(direction.x > 0.0f ? 1 : -1, direction.y > 0.0f ? 1 : -1, direction.z > 0.0f ? 1 : -1);
  // Multiplied by, where a cell's faces are met: a division per axis and
  // cell was most of the walk.
  const glm::vec3 inverse = 1.0f / direction;
  // Where the ray meets the current cell's far face across each axis: a
  // step to the next cell moves one of them, so only that one is computed
  // again (the same product as exit_of's, so the same floats).
  const auto far_face = [&](int axis) {
    if (std::isinf(inverse[axis])) return std::numeric_limits<float>::infinity();
    const int face = cell[axis] + (inverse[axis] > 0.0f ? 1 : 0);
    return (lo_[axis] + static_cast<float>(face) * cell_size_[axis] - origin[axis]) * inverse[axis];
  };
  glm::vec3 faces(far_face(0), far_face(1), far_face(2));
  // The first of them, the lowest axis where two meet, as exit_of.
  const auto leaving = [&] {
    Exit exit{faces.x, 0};
    if (faces.y < exit.t) exit = {faces.y, 1};
    if (faces.z < exit.t) exit = {faces.z, 2};
    return exit;
  };
  if (cell_occupied(cell)) {
    // The run of occupied cells the ray is in: it need not ask again
    // before it leaves the run (a hard surface's shell is some cells thick).
    Exit leaves = leaving();
    for (int run = 1; run < max_occupied_run && leaves.t < end; ++run) {
      glm::ivec3 next = cell;
      next[leaves.axis] += step[leaves.axis];
      if (next[leaves.axis] < 0 || next[leaves.axis] >= cells_per_side || !cell_occupied(next)) break;
      cell = next;
      faces[leaves.axis] = far_face(leaves.axis);
      leaves = leaving();
    }
    return {t, leaves.t - margin};
  }
  // A ray crosses at most 3 cells_per_side cells; the bound is a guard
  // (the ray then samples).
  for (int crossings = 0; crossings < 4 * cells_per_side; ++crossings) {
    const glm::ivec3 brick = cell / cells_per_brick_side;
    const int reach = empty_reach_[brick_index(brick)];
    const bool brick_empty = reach > 0;
    // The empty bricks about this one, within the bounds (only an empty
    // brick's: most crossings are of a cell in a brick that holds some).
    glm::ivec3 box_first(0), box_cells(0);
    if (brick_empty) {
      box_first = glm::max(brick - (reach - 1), glm::ivec3(0)) * cells_per_brick_side;
      box_cells = (glm::min(brick + (reach - 1), glm::ivec3(bricks_per_side - 1)) + 1) * cells_per_brick_side - box_first;
    }
    const auto [exit, axis] = brick_empty ? exit_of(box_first, box_cells, origin, inverse) : leaving();
    if (!(exit < end)) return {end, end};
    t = std::max(exit, t);
    glm::ivec3 next = cell;
    if (brick_empty) {
      // Across the box's face, in the cell the ray reaches there.
      next = glm::clamp(cell_of(origin + t * direction), box_first, box_first + box_cells - 1);
      next[axis] = step[axis] > 0 ? box_first[axis] + box_cells[axis] : box_first[axis] - 1;
    } else {
      next[axis] += step[axis];
    }
    if (next[axis] < 0 || next[axis] >= cells_per_side) return {end, end};
    cell = next;
    if (brick_empty)
      faces = glm::vec3(far_face(0), far_face(1), far_face(2));
    else
      faces[axis] = far_face(axis);
    if (cell_occupied(cell)) return {std::max(exit - margin, start), leaving().t - margin};
  }
  return {t, t};
}

long OccupancyGrid::occupied_bricks(bool surveyed_bricks) const {
  long count = 0;
  for (int z = 0; z < bricks_per_side; ++z)
    for (int y = 0; y < bricks_per_side; ++y)
      for (int x = 0; x < bricks_per_side; ++x)
        count += surveyed({x, y, z}) == surveyed_bricks && bricks_[brick_index({x, y, z})] != empty_brick;
  return count;
}

double OccupancyGrid::surveyed_empty_fraction() const {
  long empty = 0, cells = 0;
  for (int z = 0; z < cells_per_side; ++z)
    for (int y = 0; y < cells_per_side; ++y)
      for (int x = 0; x < cells_per_side; ++x) {
        if (!surveyed(glm::ivec3(x, y, z) / cells_per_brick_side)) continue;
        ++cells;
        empty += !cell_occupied({x, y, z});
      }
  return static_cast<double>(empty) / static_cast<double>(cells);
}

double OccupancyGrid::empty_fraction() const {
  return static_cast<double>(std::count(cells_.begin(), cells_.end(), 0)) / static_cast<double>(cells_.size());
}

std::string OccupancyGrid::serialized() const {
  std::string bytes(bricks_.begin(), bricks_.end());
  bytes.append(cells_.size() / 8, '\0');
  char* bits = bytes.data() + bricks_.size();
  for (std::size_t cell = 0; cell < cells_.size(); ++cell)
    if (cells_[cell]) bits[cell / 8] = static_cast<char>(bits[cell / 8] | (1 << (cell % 8)));
  return bytes;
}

std::optional<OccupancyGrid> OccupancyGrid::deserialized(const glm::vec3& lo, const glm::vec3& hi,
                                                         std::string_view bytes) {
  OccupancyGrid grid(lo, hi);
  if (bytes.size() != serialized_size()) return std::nullopt;
  for (std::size_t brick = 0; brick < grid.bricks_.size(); ++brick) {
    grid.bricks_[brick] = static_cast<std::uint8_t>(bytes[brick]);
    if (grid.bricks_[brick] > full_brick) return std::nullopt;
  }
  const std::string_view bits = bytes.substr(grid.bricks_.size());
  for (std::size_t cell = 0; cell < grid.cells_.size(); ++cell)
    grid.cells_[cell] = (static_cast<unsigned char>(bits[cell / 8]) >> (cell % 8)) & 1;
  // An empty brick's cells are what the walk steps over without looking.
  for (int z = 0; z < cells_per_side; ++z)
    for (int y = 0; y < cells_per_side; ++y)
      for (int x = 0; x < cells_per_side; ++x)
        if (grid.cell_occupied({x, y, z}) &&
            grid.bricks_[brick_index(glm::ivec3(x, y, z) / cells_per_brick_side)] == empty_brick)
          return std::nullopt;
  grid.reach_across_empty_bricks();
  return grid;
}

}  // namespace shadetree
