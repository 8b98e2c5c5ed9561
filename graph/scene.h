// The scene of a surface (or volume) graph's "render" section, as written:
// a camera, objects, lights and a background. Plain data; the surface
// driver builds its intersectable scene from it (scene/scene.h).
#pragma once

#include <array>
#include <string>
#include <vector>

namespace shadetree {

// Object to world: scale, then rotate about x, then y, then z (degrees),
// then translate.
struct TransformDesc {
  std::array<float, 3> translate{0.0f, 0.0f, 0.0f};
  std::array<float, 3> rotate_degrees{0.0f, 0.0f, 0.0f};
  std::array<float, 3> scale{1.0f, 1.0f, 1.0f};
};

enum class ObjectType { sphere, torus, plane, box, revolution, mesh };

struct ObjectDesc {
  ObjectType type = ObjectType::sphere;
  int id = 0;  // what the graph's `surface` input reads
  TransformDesc transform;
  float radius = 1.0f;                                  // sphere
  float major_radius = 1.0f, minor_radius = 0.4f;       // torus
  std::array<float, 3> half_size{1.0f, 1.0f, 1.0f};     // box
  std::vector<std::array<float, 2>> profile;            // revolution: (radius, height) points
  std::string mesh_file;                                // mesh: as written, relative to the graph file
  std::array<float, 3> color{0.8f, 0.8f, 0.8f};         // in volume scenes, where objects are not shaded by a graph
};

struct CameraDesc {
  std::array<float, 3> position{0.0f, 0.0f, 4.0f};
  std::array<float, 3> target{0.0f, 0.0f, 0.0f};
  std::array<float, 3> up{0.0f, 1.0f, 0.0f};
  float fov_degrees = 40.0f;         // vertical field of view (perspective)
  bool orthographic = false;
  float orthographic_height = 3.0f;  // world units the image spans vertically
};

enum class LightType { directional, point };

struct LightDesc {
  LightType type = LightType::directional;
  std::array<float, 3> direction{-1.0f, -1.0f, -1.0f};  // directional: the way the light travels
  std::array<float, 3> position{0.0f, 5.0f, 5.0f};      // point
  std::array<float, 3> color{1.0f, 1.0f, 1.0f};
  float intensity = 1.0f;
};

// "lit": the driver lights the graph's outputs (Lambert + Blinn-Phong);
// "none": the graph's color is the pixel (it lights itself from N, I, L).
enum class Lighting { lit, none };

struct SceneDesc {
  CameraDesc camera;
  std::vector<ObjectDesc> objects;
  std::vector<LightDesc> lights;
  std::array<float, 3> background{0.16f, 0.17f, 0.19f};
  std::string environment;  // an environment graph's file, as written: seen behind everything instead of `background`
  std::array<float, 3> ambient{0.06f, 0.06f, 0.07f};
  Lighting lighting = Lighting::lit;
  bool shadows = true;
};

// The volume of a volume graph's render section: where the ray marcher
// samples the density (Perlin & Hoffert 1989 section 3.1: each ray is
// clipped to a box bounding the hypertexture, then marched at a fixed
// step). The box is in world space, which is the space of P.
struct VolumeDesc {
  std::array<float, 3> bounds_min{0.0f, 0.0f, 0.0f};  // required; min < max on every axis
  std::array<float, 3> bounds_max{0.0f, 0.0f, 0.0f};
  float step = 0.0f;            // in the units of P; 0: the bounds' diagonal / default_steps_across
  float reference_step = 0.0f;  // the step at which opacity is the graph's; 0: the default step
  bool jitter = false;          // start each ray at a random fraction of a step (noise for banding)
};

inline constexpr float default_steps_across = 256.0f;
// Samples along one ray through the whole box (diagonal / step), at most:
// every step a graph or an option sets, the reference step included, is
// checked against it, so no march of a primary or shadow ray takes more.
inline constexpr float max_steps_across = 65536.0f;
// The thinnest bounds (on any axis; graph/parse_volume.cpp).
inline constexpr float min_volume_extent = 1e-6f;
inline constexpr float min_volume_relative_extent = 1e-5f;

// What a scene without "lights" is lit by.
std::vector<LightDesc> default_lights();

inline constexpr std::size_t max_scene_objects = 4096;
inline constexpr std::size_t max_scene_lights = 64;
inline constexpr std::size_t max_profile_points = 1024;

}  // namespace shadetree
