// The scene: what to render and how, as plain data. Reading, checking and writing it as a file:
// scene/scene_io.h. Format and every field: docs/scene-format.md.
#pragma once
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "ocean/ocean_params.h"
#include "optics/water_params.h"

namespace lagoon::scene {

// World space: y is up, the mean water surface is y = 0, +x is east and -z north (core/compass.h); metres.
// camera.gltf: take the camera from a glTF file (issue 17) instead of position, look_at and the lens.
struct CameraFromGltf {
  std::string file;  // "" = none; relative paths are resolved against the scene file's folder
  std::string name;  // the camera's (or its node's) name; "" = the file's first camera
};

struct Camera {
  glm::vec3 position{0.f, 6.f, -40.f};
  // The file's look_at, or a point computed from its yaw_deg/pitch_deg: the one aim there is to read.
  glm::vec3 look_at{0.f, 0.f, 0.f};
  float fov_deg = 55.f;  // vertical
  float near_m = 0.1f;
  float far_m = 5000.f;
  CameraFromGltf gltf;
  // The view's up direction: level (+y) for a camera the scene file places; a glTF camera's own up, so its
  // roll is kept (not a file field: it comes with camera.gltf).
  glm::vec3 up{0.f, 1.f, 0.f};
};

struct Sun {
  float elevation_deg = 35.f;
  float azimuth_deg = 330.f;  // compass: clockwise from north (-z) toward east (+x)
  float intensity = 1.f;
};

struct RenderEffects {
  bool reflection = true;  // planar reflection of what is above the water (else the sky alone)
  bool refraction = true;  // the floor and submerged objects seen through the water, coloured by the LUTs
  bool foam = true;
  bool shore_foam = true;     // a band of foam where the water is too shallow for the waves (shores, hulls)
  bool caustics = true;       // the sun focused by the waves on the floor and submerged objects
  bool caustics_blur = true;  // ... blurred with depth by the waves too short for the map and the sun's disc
  bool particles = true;      // suspended particles, seen by a camera under the water
  bool shafts = false;        // light shafts: the sun's focused beams in the water (costly on a CPU device)
  bool underwater = true;     // the water's attenuation and light along a view ray under the water
};

// Suspended particles in the water (underwater.particles): seen by a camera under the water.
struct Particles {
  float density_per_m3 = 20.f;                // mean number of particles per cubic metre
  float size_mm = 1.5f;                       // diameter
  float albedo = 0.6f;                        // how much of the light falling on them they scatter
  float patch_size_m = 2.f;                   // scale of the 4-D simplex noise that makes them patchy
  glm::vec3 drift_mps{0.03f, 0.005f, 0.02f};  // how the water carries them
  uint32_t seed = 1;                          // the same seed gives the same particles
};

struct Underwater {
  Particles particles;
};

// Scene brightness to display (render.tone_map).
enum class ToneMap { Belyaev, Clamp };  // seed 000's eq. 18; exposure and clamp only

// How the water surface is shaded: the physical optics, or seed 001 §2.1's Blinn-Phong per pixel, per vertex
// (Gouraud) or per triangle (flat), for comparing surface models as the document draws them.
enum class Shading { Physical, BlinnPhong, Gouraud, Flat };  // "physical", "blinn-phong", "gouraud", "flat"

// The water's Blinn-Phong material in the classic shading modes (reflectances, linear RGB).
struct ClassicMaterial {
  glm::vec3 ambient{0.08f, 0.2f, 0.25f};  // of the sky's light
  glm::vec3 diffuse{0.02f, 0.12f, 0.18f};
  glm::vec3 specular{0.6f, 0.6f, 0.6f};
  float shininess = 96.f;
};

struct RenderSettings {
  Shading shading = Shading::Physical;
  ClassicMaterial classic;
  uint32_t width = 1280;
  uint32_t height = 720;
  float exposure = 1.f;
  float gamma = 2.2f;
  ToneMap tone_map = ToneMap::Belyaev;  // "belyaev" / "clamp" in the file
  float tone_map_adaptation = 1.0f;     // eq. 18's L_wa, white units (optics::ToneMapParams)
  float tone_map_white = 1.5f;          // eq. 18's L_white, units of L_da
  RenderEffects effects;
};

// The sea floor: a procedural bay (a sandy floor that slopes from `depth_near_m` at `near` to
// `depth_far_m` at `far`, along the line between them; flat beyond) or a glTF mesh.
enum class SeafloorType { None, Slope, Gltf };  // "none" (open ocean), "slope", "gltf" in the file

struct Seafloor {
  SeafloorType type = SeafloorType::None;
  float depth_near_m = 0.5f;    // slope: depth below the mean water level at `near`
  float depth_far_m = 30.f;     // slope: depth at `far` and beyond
  glm::vec2 near{0.f, 0.f};     // slope: (x, z) of the shallow end
  glm::vec2 far{0.f, 200.f};    // slope: (x, z) of the deep end
  float extent_m = 600.f;       // slope: half size of the square floor around the camera's start
  std::string texture;          // PNG tiled over the floor (albedo), relative to the scene file; "" = plain
  float texture_scale_m = 2.f;  // size of one texture tile on the floor
  glm::vec3 albedo{0.76f, 0.70f, 0.55f};  // plain floor colour, or multiplied with the texture
  std::string file;                       // gltf: mesh file, relative to the scene file
};

// A hull in the water (compute/physics, docs/physics.md): its mass is `density` times its mesh's volume
// unless given, pushed by the water's pressure on its hull and damped while in the water.
struct HullBody {
  float density_kg_m3 = 500.f;           // of the model as a solid
  float mass_kg = 0.f;                   // > 0: this mass instead (inertia scaled with it)
  glm::vec3 centre_of_mass_offset{0.f};  // model coordinates, from the solid's centroid (ballast: y < 0)
  float linear_damping = 0.5f;           // 1/s, against its motion while in the water
  float quadratic_damping = 0.5f;        // 1/m
  float angular_damping = 0.5f;          // 1/s
};

// An object that rides the waves (objects[].floating): a rigid body with six degrees of freedom.
struct Floating : HullBody {
  bool enabled = false;
};

struct Object {
  std::string name;
  std::string file;             // glTF 2.0 (.gltf or .glb), relative to the scene file
  glm::vec3 position{0.f};      // metres
  glm::vec3 rotation_deg{0.f};  // yaw (about y), pitch (about x), roll (about z), applied in that order
  float scale = 1.f;
  Floating floating;
  bool lights_from_gltf = true;  // the file's KHR_lights_punctual lights join the scene's lights
};

// Where a vehicle goes (vehicles[].path): a smooth curve through the waypoints (x, z), travelled at a
// constant speed from `start_m` along it at time 0; closed when `loop`, else it stops at the last point.
struct VehiclePath {
  std::vector<glm::vec2> waypoints{{0.f, 0.f}, {40.f, 0.f}};
  float speed_mps = 3.f;
  bool loop = true;
  float start_m = 0.f;
};

// A glTF hull that follows a path (vehicles[]; docs/physics.md, Vehicles): at the surface its heave, pitch
// and roll come from buoyancy (`body`); submerged (`depth_m` > 0) it runs level at that depth.
struct Vehicle {
  std::string name;
  std::string file;  // glTF 2.0, relative to the scene file
  float scale = 1.f;
  VehiclePath path;
  float depth_m = 0.f;  // 0 = at the surface; > 0: the model's origin this far below the mean level
  HullBody body;
  float wake_strength = 1.f;     // scales the pressure its hull puts on the water (wakes); 0 = no wake
  float foam_per_s = 8.f;        // how fast foam builds behind its stern at the surface; 0 = no trail
  bool lights_from_gltf = true;  // the file's KHR_lights_punctual lights join the scene's lights
};

// The dynamic wave layer (wakes; docs/physics.md, Wakes): linear waves on a square grid around the camera,
// forced by the vehicles' hulls and added to the ocean.
struct Wakes {
  bool enabled = true;               // runs when some vehicle makes a wake
  uint32_t resolution = 512;         // cells per side
  float cell_size_m = 0.25f;         // so the window is resolution x cell_size_m wide
  float damping_per_s = 0.02f;       // of every wave
  float border_m = 16.f;             // width of the absorbing border at the window's edges
  float step_s = 0.1f;               // the layer's time step
  float history_s = 30.f;            // a frame's layer starts this long before it (or at 0)
  float foam_lifetime_s = 15.f;      // a foam trail fades to 5 % in this time
  float foam_spread_m2_s = 0.1f;     // and widens as it ages: its variance across grows by 2 this per second
  bool felt_by_bodies = true;        // floating bodies and surface vehicles ride the wakes
  uint32_t bodies_resolution = 128;  // cells per side of the bodies' CPU layer (same window width)
};

// Sediment stirred up from the floor by the vehicles (docs/physics.md, Sediment): Gaussian clouds that
// burst from the floor, drift, spread and settle, drawn as turbidity and as earth-coloured grains.
struct Sediment {
  bool enabled = true;                    // vehicles near the floor stir it up
  float release_height_m = 1.5f;          // a hull's lowest point closer to the floor than this stirs it
  float release_g_per_s = 10.f;           // at the floor, falling linearly to 0 at release_height_m
  float rise_m = 0.8f;                    // height of a new cloud's centre above the floor
  float radius_m = 0.5f;                  // a new cloud's standard deviation
  float settling_mps = 0.01f;             // the particles' settling velocity
  float diffusivity_m2_s = 0.005f;        // turbulent diffusivity that spreads the clouds
  glm::vec2 current_mps{0.f, 0.f};        // drift (x, z)
  float interval_s = 1.f;                 // one cloud per stirring vehicle per interval
  float max_age_s = 600.f;                // older clouds are dropped
  float attenuation_m2_per_g = 0.4f;      // mass-specific beam attenuation of the particles
  glm::vec3 colour{0.55f, 0.47f, 0.36f};  // their albedo, linear RGB
  float burst_s = 0.5f;                   // a new cloud is thrown up and out over about this time
  float grains_per_g = 4.f;               // grains drawn per gram in the water (seed 002's particles)
  float grain_size_mm = 10.f;             // their diameter as drawn (clumps: one grain is sub-pixel)
};

struct PointLight {
  glm::vec3 position{0.f, 5.f, 0.f};
  glm::vec3 colour{1.f, 0.9f, 0.7f};  // linear RGB
  float intensity = 1.f;              // irradiance at 1 m, in units of the sun's (white = 1)
  float range_m = 50.f;               // beyond this the light has no effect
  // A spot light: the direction it shines and its cone (full inside inner, none outside outer); an outer
  // angle of 180° is a point light.
  glm::vec3 spot_direction{0.f, -1.f, 0.f};
  float spot_inner_deg = 0.f;
  float spot_outer_deg = 180.f;
};

struct Scene {
  std::filesystem::path source;  // file it came from ("" when parsed from memory)
  Camera camera;
  Sun sun;
  Seafloor seafloor;
  std::vector<Object> objects;
  std::vector<Vehicle> vehicles;
  Wakes wakes;
  Sediment sediment;
  std::vector<PointLight> lights;
  ocean::OceanParams ocean;
  optics::WaterParams water;  // water.table, seafloor.texture/file and objects[].file, when relative, are
                              // resolved against the scene file's folder
  Underwater underwater;
  RenderSettings render;
  float time_s = 0.f;  // simulation time of the rendered frame
  // The floating objects and surface vehicles start at rest where the scene puts them at this time (a frame
  // before it shows them there), and are simulated from it at a fixed step (world/floating_objects.h).
  float bodies_start_s = 0.f;
};

// The most physics one frame may ask for: the floating objects and surface vehicles are brought to its time
// from where they are (a scene file's frame: from bodies_start_s), and the harbour's three hulls took 23 s
// for a 96 x 54 frame at 120 s, so a frame may take at most 300 hull-seconds (about 20 s on lavapipe) and
// is refused above that with the fix (issue 36, docs/physics.md).
inline constexpr double kMaxBodyHullSecondsPerFrame = 300;

}  // namespace lagoon::scene
