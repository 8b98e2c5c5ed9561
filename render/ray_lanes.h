// The live rays of one packet of the volume march (render/volume_driver.cpp),
// a field per array, a lane per ray: each stage of a step runs over the few
// fields it needs, in plain loops over floats, where it followed a pointer
// to each ray's record. The fields a step reads or writes at every sample
// are here; what only some samples touch stays in the ray's record (the
// marcher's MarchingRay), at `record[lane]`. A ray that ends leaves its
// lane to the last lane's ray: the lanes stay dense, and a ray's samples
// do not depend on its lane.
//
// Segment k of a ray covers t in [entry + k step, min(entry + (k + 1) step,
// exit)]; its sample lies `jitter` of the way along it (the middle without
// jitter). Each segment composites with its own length, so a constant
// density gives exactly the transmittance of the box's thickness whatever
// the step (1989: opacity is "a function of both density and step-size").
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/vec3.hpp>

namespace shadetree {

struct RayLanes {
  explicit RayLanes(float step) : step(step) {}

  // A ray from `from` along the unit `direction`, through [entry_t, exit_t],
  // from segment `first_segment` (-1: the probe before the entry), whose
  // record is `record_index`.
  void add(const glm::vec3& from, const glm::vec3& direction, float entry_t, float exit_t, float jitter_fraction,
           int first_segment, std::uint32_t record_index) {
    for (int c = 0; c < 3; ++c) {
      origin[c].push_back(from[c]);
      along[c].push_back(direction[c]);
      color[c].push_back(0.0f);
    }
    entry.push_back(entry_t);
    exit.push_back(exit_t);
    jitter.push_back(jitter_fraction);
    segment.push_back(first_segment);
    previous_t.push_back(0.0f);
    previous_density.push_back(0.0f);
    occupied_until.push_back(-std::numeric_limits<float>::infinity());
    alpha.push_back(0.0f);
    record.push_back(record_index);
  }

  // The ray of lane `from` takes lane `to`; a step moves live rays into
  // the lanes of ended ones, then `truncate`s the rest.
  void move(std::size_t from, std::size_t to) {
    for_each_field([&](auto& field) { field[to] = field[from]; });
  }
  void truncate(std::size_t count) {
    for_each_field([&](auto& field) { field.resize(count); });
  }

  std::size_t size() const { return record.size(); }
  bool empty() const { return record.empty(); }

  // The ray of a lane sets out afresh from `from` along the unit
  // `direction` through [0, exit_t], with the probe before its entry first
  // (a bent ray).
  void set_out(std::size_t lane, const glm::vec3& from, const glm::vec3& direction, float exit_t) {
    for (int c = 0; c < 3; ++c) {
      origin[c][lane] = from[c];
      along[c][lane] = direction[c];
    }
    entry[lane] = 0.0f;
    exit[lane] = exit_t;
    segment[lane] = -1;
    occupied_until[lane] = -std::numeric_limits<float>::infinity();
  }

  float segment_start(std::size_t lane, int k) const { return entry[lane] + static_cast<float>(k) * step; }
  float segment_length(std::size_t lane, int k) const {
    return std::min(step, exit[lane] - segment_start(lane, k));
  }
  float sample_t(std::size_t lane, int k) const {
    return k < 0 ? entry[lane] - (1.0f - jitter[lane]) * step
                 : segment_start(lane, k) + jitter[lane] * segment_length(lane, k);
  }
  float segment_start(std::size_t lane) const { return segment_start(lane, segment[lane]); }
  float segment_length(std::size_t lane) const { return segment_length(lane, segment[lane]); }
  float sample_t(std::size_t lane) const { return sample_t(lane, segment[lane]); }
  // Whether the ray has a segment left to march.
  bool has_segments_left(std::size_t lane) const { return segment_start(lane) < exit[lane]; }

  glm::vec3 origin_of(std::size_t lane) const { return {origin[0][lane], origin[1][lane], origin[2][lane]}; }
  glm::vec3 along_of(std::size_t lane) const { return {along[0][lane], along[1][lane], along[2][lane]}; }
  glm::vec3 point(std::size_t lane, float t) const {
    return {origin[0][lane] + t * along[0][lane], origin[1][lane] + t * along[1][lane],
            origin[2][lane] + t * along[2][lane]};
  }
  glm::vec3 color_of(std::size_t lane) const { return {color[0][lane], color[1][lane], color[2][lane]}; }

  // Moves the ray of a lane on to its last segment whose sample lies
  // before `t` (never past its last segment), as stepping one segment at a
  // time would, and says how many it passed. Over whole segments the
  // sample moves monotonically, so the ray first jumps to about where it
  // passes `t`.
  int advance_to_last_sample_before(std::size_t lane, float t) {
    int& k_next = segment[lane];
    const float from = entry[lane], to = exit[lane];
    const auto whole_and_before = [&](int k) { return to - segment_start(lane, k) >= step && sample_t(lane, k) < t; };
    const int first = k_next;
    const float guess = std::min((t - from) / step, (to - from) / step);
    if (guess > static_cast<float>(k_next) + 2.0f && guess < 1e9f) {
      int k = static_cast<int>(guess);
      while (k > k_next && !whole_and_before(k)) --k;
      k_next = k;
    }
    while (segment_start(lane, k_next + 1) < to && sample_t(lane, k_next + 1) < t) ++k_next;
    return k_next - first;
  }

  // Front to back: t = alpha_k (1 - alpha); color += t color_k.
  void composite(std::size_t lane, float segment_alpha, const glm::vec3& sample_color) {
    const float weight = segment_alpha * (1.0f - alpha[lane]);
    for (int c = 0; c < 3; ++c) color[c][lane] += weight * sample_color[c];
    alpha[lane] += weight;
  }

  // A field per array, a lane per ray.
  float step;  // every segment's length but a ray's last
  std::vector<float> origin[3], along[3];
  std::vector<float> entry, exit, jitter;
  std::vector<int> segment;  // the next one; -1: the probe before the entry, for the first gradient
  std::vector<float> previous_t, previous_density;
  std::vector<float> occupied_until;  // no need to look for empty space before
  std::vector<float> color[3], alpha;
  std::vector<std::uint32_t> record;

 private:
  // Every field's array, so that moving and truncating a lane miss none.
  template <class Visit>
  void for_each_field(Visit visit) {
    for (int c = 0; c < 3; ++c) {
      visit(origin[c]);
      visit(along[c]);
      visit(color[c]);
    }
    visit(entry);
    visit(exit);
    visit(jitter);
    visit(segment);
    visit(previous_t);
    visit(previous_density);
    visit(occupied_until);
    visit(alpha);
    visit(record);
  }
};

}  // namespace shadetree
