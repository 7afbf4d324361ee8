#include "scene/world_blocks.h"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "scene/effects.h"
#include "shared/sediment.h"

namespace lagoon::scene {
namespace {

void read_effects(ObjectReader& r, RenderEffects& e) {
  for (const EffectKind& k : kEffects) r.flag(k.name, e.*k.flag, k.doc);
}

}  // namespace

void read_particles(ObjectReader& r, Particles& p) {
  r.number("density_per_m3", p.density_per_m3, Bounds::between(0, 1000), "1/m³",
           "Mean number of particles per cubic metre of water; 0 = none.");
  r.number("size_mm", p.size_mm, Bounds::above_up_to(0, 100), "mm", "Particle diameter.");
  r.number("albedo", p.albedo, Bounds::between(0, 1), "",
           "Share of the light falling on a particle that it scatters (sand and plankton: 0.3 to 0.8).");
  r.number("patch_size_m", p.patch_size_m, Bounds::above_up_to(0, 1000), "m",
           "Size of the clouds the particles gather in: the scale of the 4-D simplex noise (x, y, z, t) that "
           "sets their local density.");
  r.vec3("drift_mps", p.drift_mps, "m/s", "Velocity of the water carrying the particles.");
  r.integer("seed", p.seed, Bounds::between(0, 4294967295.0), "",
            "Random seed: the same seed gives the same particles, another seed others.");
}

void read_underwater(ObjectReader& r, Underwater& u) {
  r.block("particles", u.particles, read_particles, "Suspended particles (seed 002's 4-D simplex noise).");
}

void read_seafloor(ObjectReader& r, Seafloor& f) {
  r.choice("type", f.type,
           std::vector<std::pair<std::string, SeafloorType>>{
               {"none", SeafloorType::None}, {"slope", SeafloorType::Slope}, {"gltf", SeafloorType::Gltf}},
           "\"none\" = open ocean with no visible floor; \"slope\" = a procedural sandy bay (see Seafloor "
           "below); \"gltf\" = a mesh from `file`.");
  r.number("depth_near_m", f.depth_near_m, Bounds::between(-100, 11000), "m",
           "slope: depth of the floor below the mean water level at `near`; < 0 rises above the water (a "
           "beach: the waves break on it and end at the shoreline).");
  r.number("depth_far_m", f.depth_far_m, Bounds::between(0, 11000), "m",
           "slope: depth at `far` and beyond; the floor is flat past both ends.");
  r.rule("depth_far_m", f.depth_far_m >= f.depth_near_m, ">= depth_near_m",
         "got depth_far_m " + format_number(f.depth_far_m) + " and depth_near_m " +
             format_number(f.depth_near_m) +
             "; the floor deepens from near to far, so swap the depths or "
             "swap near and far");
  r.vec2("near", f.near, "m", "slope: horizontal position of the shallow end.");
  r.vec2("far", f.far, "m", "slope: horizontal position of the deep end; the slope runs along near -> far.");
  r.rule("far", f.far != f.near, "different from near",
         "near and far set the direction of the slope; move far to where the water is deepest");
  r.number("extent_m", f.extent_m, Bounds::above_up_to(0, 100000), "m",
           "slope: half the side of the square floor, centred on the camera's start position.");
  r.text("texture", f.texture,
         "PNG tiled over the floor as its albedo, relative to the scene file's folder; \"\" = plain "
         "`albedo`.");
  r.number("texture_scale_m", f.texture_scale_m, Bounds::above_up_to(0, 1000), "m",
           "Side of one texture tile on the floor.");
  r.vec3("albedo", f.albedo, "[r, g, b]", Bounds::between(0, 1), "",
         "Linear floor colour; multiplies the texture when there is one.");
  r.text("file", f.file, "gltf: the floor mesh (.gltf or .glb), relative to the scene file's folder.");
  // Both directions are checked so a file never carries a mesh that is silently ignored.
  r.rule("file", f.type != SeafloorType::Gltf || !f.file.empty(), "a file name when type is \"gltf\"",
         "type \"gltf\" reads the floor from a mesh; give its path, e.g. \"file\": \"bay.glb\"");
  r.rule("file", f.type != SeafloorType::Slope || f.file.empty(), "left out when type is \"slope\"",
         "got " + describe_value(nlohmann::json(f.file)) +
             "; a slope is generated, not loaded: remove `file`, or set type \"gltf\" to use the mesh");
}

void read_hull_body(ObjectReader& r, HullBody& f) {
  r.number("density_kg_m3", f.density_kg_m3, Bounds::between(1, 20000), "kg/m^3",
           "Density of the model as a solid; its mass is this times the mesh's volume. Sea water is 1025: "
           "half of that floats half under.");
  r.number("mass_kg", f.mass_kg, Bounds::between(0, 1e9), "kg",
           "The body's mass; 0 = density_kg_m3 times the mesh's volume. The inertia is scaled with it.");
  r.vec3("centre_of_mass_offset", f.centre_of_mass_offset, "[x, y, z]", Bounds::between(-1000, 1000), "m",
         "Moves the centre of mass from the solid's centroid, in the model's coordinates: ballast low in a "
         "hull (y < 0) keeps it upright. A uniform solid buoy or boat with its weight high capsizes, as it "
         "would.");
  r.number("linear_damping", f.linear_damping, Bounds::between(0, 100), "1/s",
           "Damping of its motion while in the water: a force of this times its mass and velocity.");
  r.number("quadratic_damping", f.quadratic_damping, Bounds::between(0, 100), "1/m",
           "Damping that grows with speed: this times its mass, speed and velocity.");
  r.number("angular_damping", f.angular_damping, Bounds::between(0, 100), "1/s",
           "Damping of its rotation while in the water.");
}

void read_floating(ObjectReader& r, Floating& f) {
  r.flag(
      "enabled", f.enabled,
      "Ride the waves: the model becomes a rigid body pushed by the water's pressure on its mesh. At time 0 "
      "it is at rest at `position` (x, z) and `rotation_deg`, at the height where still water carries it; "
      "a body that cannot float starts at `position` and sinks (docs/physics.md). Its mesh must be closed.");
  read_hull_body(r, f);
}

void read_vehicle_path(ObjectReader& r, VehiclePath& p) {
  r.points2("waypoints", p.waypoints, 2, 256, "m",
            "Points (x, z) the vehicle passes through, in order; the path is a smooth curve (Catmull-Rom) "
            "through them.");
  r.number("speed_mps", p.speed_mps, Bounds::between(0, 60), "m/s",
           "Speed along the path; 0 = it stays put.");
  r.flag("loop", p.loop,
         "true: the path closes from the last waypoint back to the first and repeats; false: the vehicle "
         "stops at the last waypoint.");
  r.number("start_m", p.start_m, Bounds::between(0, 1e7), "m",
           "Distance along the path where the vehicle is at time 0.");
}

void read_vehicle(ObjectReader& r, Vehicle& v) {
  r.text("name", v.name, "Label for messages and tools (lagoon probe --object).");
  r.text("file", v.file,
         "glTF 2.0 model (.gltf or .glb) with its bow toward +z, relative to the scene file.");
  r.rule("file", !v.file.empty(), "a file name (required)",
         "every vehicle is loaded from a glTF file; add e.g. \"file\": \"assets/boat.gltf\"");
  r.number("scale", v.scale, Bounds::above_up_to(0, 1000), "", "Uniform scale of the model.");
  r.block("path", v.path, read_vehicle_path, "Where the vehicle goes; its heading follows the path.");
  r.number(
      "depth_m", v.depth_m, Bounds::between(0, 11000), "m",
      "0 = at the surface: heave, pitch and roll come from buoyancy (`body`), so the mesh must be closed; "
      "> 0 = submerged (an AUV): the model's origin runs level at this depth below the mean water level.");
  r.block("body", v.body, read_hull_body, "Mass and damping of a surface vehicle's hull (docs/physics.md).");
  r.number("wake_strength", v.wake_strength, Bounds::between(0, 10), "",
           "Scales the pressure of its hull on the water, which makes its wake (`wakes`): 1 = the hull's "
           "draught; 0 = no wake.");
  r.number(
      "foam_per_s", v.foam_per_s, Bounds::between(0, 1000), "1/s",
      "How fast foam builds behind its stern (propeller wash) and, at 0.3 of it, at its bow, while it "
      "runs at the surface: coverage per second where the hull passes, saturating at 1 (`wakes`); 0 = no "
      "trail. Submerged vehicles leave none.");
  r.flag("lights_from_gltf", v.lights_from_gltf,
         "The model's KHR_lights_punctual lights (running lights, an AUV's lamp) join the scene's lights and "
         "move with it, as objects[].lights_from_gltf.");
}

// A still frame replays history_s / step_s steps of the layer, each over resolution² cells on the device and
// bodies_resolution² on the CPU (issue 36). Legal values could ask for hundreds of times the defaults' work
// (1024 / 1024 took 90 s for a 96 x 54 frame at t = 3 s), so the product is bounded at about 1.2 times the
// defaults' 83.6 million cell-steps and anything above is refused with its cost and the fix.
constexpr double kMaxWakeCellStepsPerFrame = 100e6;

void check_wake_cost(ObjectReader& r, const Wakes& w) {
  const double cells = double(w.resolution) * w.resolution +
                       (w.felt_by_bodies ? double(w.bodies_resolution) * w.bodies_resolution : 0.0);
  const double steps = w.step_s > 0 ? std::ceil(w.history_s / w.step_s) : 0.0;
  const double cost = steps * cells;
  const bool holds = !w.enabled || cost <= kMaxWakeCellStepsPerFrame;
  r.rule("step_s", holds,
         "history_s / step_s x (resolution² + bodies_resolution²) <= 100 million cell-steps a frame",
         holds ? std::string()
               : "history_s " + format_number(w.history_s) + " / step_s " + format_number(w.step_s) + " = " +
                     format_number(steps) + " steps of " + format_number(cells) + " cells is " +
                     format_number(std::round(cost / 1e6)) +
                     " million cell-steps a frame (the defaults: 83.6 million); raise step_s to " +
                     format_number(std::ceil(w.history_s * cells / kMaxWakeCellStepsPerFrame * 1000.0) /
                                   1000.0) +
                     ", shorten history_s to " +
                     format_number(std::floor(kMaxWakeCellStepsPerFrame * w.step_s / cells)) +
                     " or lower resolution / bodies_resolution");
}

void read_wakes(ObjectReader& r, Wakes& w) {
  r.flag(
      "enabled", w.enabled,
      "Run the dynamic wave layer when a vehicle makes a wake; false = vehicles leave the water untouched.");
  r.power_of_two(
      "resolution", w.resolution, 64, 1024, "cells",
      "Cells per side of the layer's square window around the camera (its cost grows with the square; "
      "lagoon bench wakes).");
  r.number("cell_size_m", w.cell_size_m, Bounds::between(0.02, 10), "m",
           "Size of a cell: the window is resolution x cell_size_m wide. Waves shorter than 4 cells are not "
           "resolved: keep it below a quarter of the shortest wake wave, two thirds of 2 pi speed^2 / g at "
           "the cusps.");
  r.number(
      "damping_per_s", w.damping_per_s, Bounds::between(0, 10), "1/s",
      "Damping of every wave of the layer; the wake of a passing boat fades over about 1 / this seconds.");
  r.number("border_m", w.border_m, Bounds::above_up_to(0, 10000), "m",
           "Width of the absorbing border inside the window's edges, where waves leaving it are damped away "
           "instead of coming back; at least a wake wavelength.");
  r.rule("border_m", w.border_m < 0.5 * w.resolution * w.cell_size_m,
         "< half the window (resolution x cell_size_m / 2)",
         "got border_m " + format_number(w.border_m) + " for a window of " +
             format_number(w.resolution * w.cell_size_m) +
             " m; make the border narrower or the window larger");
  r.number("step_s", w.step_s, Bounds::between(0.005, 1), "s",
           "Time step of the layer; any step is stable (each wave is advanced exactly), shorter ones follow "
           "the hulls more closely in time and cost more.");
  r.number("history_s", w.history_s, Bounds::between(0, 3600), "s",
           "A frame's layer is computed from still water this long before the frame's time (or from time 0, "
           "so a sequence's frames before this time step on from each other), so a still frame at a late "
           "time costs history_s / step_s steps. Waves older than this are left out: the harbour's boat "
           "leaves waves in the window for longer (docs/datasets.md).");
  r.number("foam_lifetime_s", w.foam_lifetime_s, Bounds::above_up_to(0, 3600), "s",
           "The vehicles' foam trails fade to 5 % (e^-3) of their coverage in this time.");
  r.number("foam_spread_m2_s", w.foam_spread_m2_s, Bounds::between(0, 100), "m²/s",
           "How fast a trail widens as it ages (seed 002: as wide as the hull at its start, wider toward its "
           "end): its foam diffuses sideways, the variance across it growing by 2 x this per second, so a "
           "trail of beam b is about sqrt(b^2 + 8 x this x age) wide. 0 = a band of fixed width. One step "
           "spreads at most 0.24 cell^2, so a finer cell_size_m or a longer step_s caps it.");
  r.flag("felt_by_bodies", w.felt_by_bodies,
         "Floating objects and surface vehicles ride the wakes (a vehicle every wake but its own), and "
         "`lagoon probe --at` includes them; the layer then also runs on the CPU, around the bodies.");
  r.power_of_two(
      "bodies_resolution", w.bodies_resolution, 16, 1024, "cells",
      "Cells per side of the bodies' layer, over the same window width as the picture's: coarser "
      "cells leave out the shortest wake waves, which a hull averages out; its cost on the CPU grows "
      "with the square.");
  r.rule("bodies_resolution", w.bodies_resolution <= w.resolution, "<= resolution",
         "got " + std::to_string(w.bodies_resolution) + " for a picture layer of " +
             std::to_string(w.resolution) + " cells; the bodies' layer is at most as fine as the picture's");
  check_wake_cost(r, w);
}

void read_sediment(ObjectReader& r, Sediment& s) {
  r.flag("enabled", s.enabled,
         "Vehicles that pass near the floor (the slope or a glTF floor) stir up sediment.");
  r.number("release_height_m", s.release_height_m, Bounds::between(0, 100), "m",
           "A hull whose lowest point (or, submerged, its propeller wash there) comes closer to the floor "
           "than this stirs it up; 0 = never.");
  r.number("release_g_per_s", s.release_g_per_s, Bounds::between(0, 1e6), "g/s",
           "Mass stirred up per second by a hull touching the floor, falling linearly to 0 at "
           "release_height_m.");
  r.number("rise_m", s.rise_m, Bounds::between(0, 100), "m",
           "How high above the floor the wash throws a new cloud (its centre).");
  r.number("radius_m", s.radius_m, Bounds::above_up_to(0, 100), "m",
           "A new cloud's size: the standard deviation of its Gaussian.");
  r.number("settling_mps", s.settling_mps, Bounds::between(0, 10), "m/s",
           "The particles' settling velocity: Stokes' law gives ~0.01 m/s for fine sand (0.1 mm), ~0.001 "
           "for silt (0.03 mm). The water clears once the clouds have sunk to the floor.");
  r.number("diffusivity_m2_s", s.diffusivity_m2_s, Bounds::between(0, 100), "m²/s",
           "Turbulent diffusivity K: a cloud's variance grows by 2 K per second.");
  r.vec2("current_mps", s.current_mps, "m/s", "The water's drift (x, z) that carries the clouds.");
  r.rule("current_mps", std::abs(s.current_mps.x) <= 20 && std::abs(s.current_mps.y) <= 20,
         "each component within ±20 m/s", "tidal currents reach a few m/s; give the drift in m/s");
  r.number("interval_s", s.interval_s, Bounds::between(0.05, 60), "s",
           "A stirring vehicle releases one cloud per interval; shorter is smoother and costs more clouds "
           "(the frame draws the " +
               std::to_string(LAGOON_MAX_SEDIMENT_PUFFS) + " densest).");
  r.number("max_age_s", s.max_age_s, Bounds::between(1, 86400), "s",
           "Clouds older than this are dropped; at the defaults they have settled long before.");
  r.number("attenuation_m2_per_g", s.attenuation_m2_per_g, Bounds::between(0, 100), "m²/g",
           "Beam attenuation per gram of suspended sediment: 0.1-1 m²/g for mineral particles of a few "
           "micrometres to tens (so 10 g/m³ at 0.4 m²/g is 4 per metre).");
  r.vec3("colour", s.colour, "[r, g, b]", Bounds::between(0, 1), "",
         "Albedo of the particles (linear RGB): the light a cloud scatters toward the camera is this times "
         "the light at its depth.");
  r.number("burst_s", s.burst_s, Bounds::between(0, 60), "s",
           "The wash's burst (seed 002): a new cloud leaves the floor as a point and is thrown up to rise_m "
           "and out to radius_m as 1 - e^(-age / burst_s); 0 = born at its full height and size.");
  r.number("grains_per_g", s.grains_per_g, Bounds::between(0, 1000), "1/g",
           "Earth-coloured grains drawn per gram of a cloud still in the water (seed 002's particles), each "
           "where the cloud's Gaussian puts it, at most " +
               std::to_string(LAGOON_SEDIMENT_MAX_GRAINS) + " a cloud; 0 = the turbidity alone.");
  r.number("grain_size_mm", s.grain_size_mm, Bounds::above_up_to(0, 100), "mm",
           "The grains' diameter as drawn (at least 1.5 pixels, fainter when smaller, as the suspended "
           "particles).");
}

void read_object(ObjectReader& r, Object& o) {
  r.text("name", o.name, "Label for messages and tools; need not be unique.");
  r.text("file", o.file, "glTF 2.0 model (.gltf or .glb), relative to the scene file's folder.");
  r.rule("file", !o.file.empty(), "a file name (required)",
         "every object is loaded from a glTF file; add e.g. \"file\": \"buoy.glb\"");
  r.vec3("position", o.position, "m", "Where the model's origin goes (y up; the mean water level is y = 0).");
  r.vec3("rotation_deg", o.rotation_deg, "[yaw, pitch, roll]", Bounds::between(-360, 360), "deg",
         "Yaw: the compass direction the model's front (+z) faces, clockwise from north (-z) toward east "
         "(+x) like camera.yaw_deg; then pitch (positive raises the model's +z end), then roll about the "
         "model's z axis; see Objects below.");
  r.number("scale", o.scale, Bounds::above_up_to(0, 1000), "", "Uniform scale of the model.");
  r.block("floating", o.floating, read_floating, "An object that rides the waves (docs/physics.md).");
  r.flag("lights_from_gltf", o.lights_from_gltf,
         "The model's KHR_lights_punctual lights (a buoy's lamp, a boat's lanterns) join the scene's lights "
         "and move with it; spot lights keep their cone (docs/scene-format.md, Objects).");
}

void read_light(ObjectReader& r, PointLight& l) {
  r.vec3("position", l.position, "m", "Position of the light.");
  r.vec3("colour", l.colour, "[r, g, b]", Bounds::between(0, 100), "",
         "Linear RGB colour; multiplied by intensity.");
  r.number("intensity", l.intensity, Bounds::between(0, 1000000), "",
           "Irradiance 1 m from the light, in units of the reference sun's (1); falls off with the square of "
           "the distance.");
  r.number("range_m", l.range_m, Bounds::above_up_to(0, 100000), "m",
           "Beyond this distance the light has no effect (bounds its cost).");
  r.vec3("spot_direction", l.spot_direction, "m", "A spot light: the direction it shines (any length).");
  r.number("spot_inner_deg", l.spot_inner_deg, Bounds::between(0, 180), "deg",
           "A spot light: half-angle of the cone it lights fully.");
  r.number(
      "spot_outer_deg", l.spot_outer_deg, Bounds::between(0, 180), "deg",
      "A spot light: half-angle beyond which it lights nothing, fading from spot_inner_deg; 180 = a point "
      "light (KHR_lights_punctual's spot cone).");
  r.rule("spot_outer_deg", l.spot_outer_deg > l.spot_inner_deg, "> spot_inner_deg",
         "the light fades from the inner to the outer angle; raise spot_outer_deg");
  r.rule("spot_direction", glm::length(l.spot_direction) > 0, "not [0, 0, 0]",
         "give the direction the spot shines, e.g. [0, -1, 0] straight down");
}

void read_classic(ObjectReader& r, ClassicMaterial& m) {
  r.vec3("ambient", m.ambient, "[r, g, b]", Bounds::between(0, 10), "",
         "Ambient reflectance: the part of the sky's light the water returns regardless of direction.");
  r.vec3("diffuse", m.diffuse, "[r, g, b]", Bounds::between(0, 10), "",
         "Diffuse reflectance: times the light's irradiance (n . l).");
  r.vec3("specular", m.specular, "[r, g, b]", Bounds::between(0, 10), "",
         "Specular reflectance of the highlight, (n . h)^shininess with h half-way between the light and the "
         "viewer.");
  r.number("shininess", m.shininess, Bounds::between(1, 10000), "",
           "Exponent of the highlight: higher = smaller, sharper highlights.");
}

void read_render(ObjectReader& r, RenderSettings& s) {
  r.choice(
      "shading", s.shading,
      std::vector<std::pair<std::string, Shading>>{{"physical", Shading::Physical},
                                                   {"blinn-phong", Shading::BlinnPhong},
                                                   {"gouraud", Shading::Gouraud},
                                                   {"flat", Shading::Flat}},
      "How the water is shaded: \"physical\" = Fresnel reflection and refraction with the optics LUTs; "
      "the classic modes of seed 001 section 2.1 light it with Blinn-Phong (render.classic) from the sun, "
      "the point lights and the sky: \"blinn-phong\" per pixel, \"gouraud\" per vertex, \"flat\" per "
      "triangle (docs/models.md).");
  r.block("classic", s.classic, read_classic, "The water's material in the classic shading modes.");
  r.integer("width", s.width, Bounds::between(16, 8192), "px", "Output image width.");
  r.integer("height", s.height, Bounds::between(16, 8192), "px", "Output image height.");
  r.number("exposure", s.exposure, Bounds::between(0.01, 100), "",
           "Linear multiplier on scene brightness before display encoding; 2 is one stop brighter.");
  r.number("gamma", s.gamma, Bounds::between(1, 3), "", "Display gamma used to encode the output.");
  r.choice(
      "tone_map", s.tone_map,
      std::vector<std::pair<std::string, ToneMap>>{{"belyaev", ToneMap::Belyaev}, {"clamp", ToneMap::Clamp}},
      "Scene brightness to display: \"belyaev\" = Belyaev's eq. 18 (Tumblin-Rushmeier with white-point "
      "compression, docs/optics.md); \"clamp\" = exposure, then each channel clipped at 1.");
  r.number("tone_map_adaptation", s.tone_map_adaptation, Bounds::between(0.001, 1000), "",
           "Eq. 18's world adaptation luminance L_wa in white units (a white surface under the sun and sky = "
           "1). `lagoon sky` fits it to the sky image (docs/optics.md).");
  r.number("tone_map_white", s.tone_map_white, Bounds::between(0.1, 100), "",
           "Eq. 18's L_white: the compressed luminance L_d that shows as display white. `lagoon sky` fits it "
           "to the sky image (docs/optics.md).");
  r.block("effects", s.effects, read_effects, "Parts of the image that can be switched off.");
}

}  // namespace lagoon::scene
