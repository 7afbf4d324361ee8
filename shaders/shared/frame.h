// Frame constants of the ocean renderer (engine/render/ocean_renderer.cpp). Uniform buffer, std140.
// Radiances are in "white units" (render/sky_light.h): a white Lambertian surface under sun and sky = 1.
#ifndef LAGOON_SHARED_FRAME_H
#define LAGOON_SHARED_FRAME_H
#include "shared/direct_waves.h"
#include "shared/interop.h"
#include "shared/limits.h"
#include "shared/sky_model.h"

// The sky pass (render/sky.frag) binds only the frame.
#define LAGOON_SKY_BIND_FRAME 0

LAGOON_GPU_BEGIN
struct FrameUniforms {
  // Read by no shader, on purpose. Debian's lavapipe (Mesa 22.3) inlines the uniforms a shader's branches
  // read and compiles that variant at the draw; for a uniform buffer (not push constants) it files their
  // offsets where it does not read them back, so it inlines the block's first word instead. With the view
  // matrix here, every turn of the camera compiled the surface seen from below again, 0.5 s a frame; with
  // the picture's size here, a shader that folded it kept a variant per draw and memory grew 2 MiB a frame.
  // A word no shader reads folds nothing, and lavapipe gives up inlining after its first try (docs/
  // evaluation.md, "The below-surface recompile").
  vec4 unread;
  vec4 screen;  // x = width, y = height (pixels), zw = 1 / (width, height)
  mat4 view_proj;
  mat4 inv_view_proj;
  vec4 camera_pos;      // xyz metres, w = time s
  vec4 sun_dir;         // xyz towards the sun, w = index of refraction of the water
  vec4 sun_irradiance;  // rgb on a surface facing the sun, w unused
  vec4 sky_radiance;    // rgb of a uniform sky with the model's E_sky, w = cos of the sun disc's radius
  vec4 sun_disc;        // rgb radiance of the solar disc, w = unused
  vec4 water_deep;      // rgb deep-water colour (LUT), w = foam albedo
  vec4 grid;     // x = finest spacing m, y = cells per half side (shared/clipmap.h), z = haze distance m,
                 // w = cascade count
  vec4 clipmap;  // x = levels, y = fade of the finest level, z = morph zone in cells (shared/clipmap.h)
  vec4 cascade_patch;  // patch size (m) of cascades 0..3
  vec4 cascade_layer;  // array layer of cascades 0..3
  vec4 cascade_texel;  // L/N (m) of cascades 0..3
  vec4 cascade_mss;    // mean square slope (ocean/slope_statistics.h) of cascades 0..3
  vec4 glint;          // x = mean square slope of the waves shorter than the last cascade (to 1 cm),
                       // y = foam onset on the whole sea's Jacobian, z = significant wave height m
                       // for the shore foam (0 = none), w = foam width (ocean/whitecaps.h)
  vec4 post;           // x = exposure, y = display gamma, z = tone-map m, w = tone-map exponent
  vec4 post2;          // x = tone-map white, y = tone-map world adaptation, z = tone map on (1) / clamp (0)
  vec4 lut;            // x = r_max m, y = h_max m of the colour LUTs, z = refraction on, w = light scale
  vec4 lights;         // x = number of point lights in the light buffer, yzw unused
  vec4 underwater;     // x = d_max m, y = z_max m of the underwater tables (optics/underwater.h),
                       // z = 1 when the camera is under the water surface, w = unused
  vec4 floor_below;    // x = depth m of the floor under the camera (0 = none known), y = its mean albedo
                       // (water.bottom_albedo), zw unused: what total internal reflection shows from below
  vec4 caustics;  // xy = world xz of the caustic window's corner, z = its cell size m, w = cells per side
                  // (0 = no caustics) (shared/caustics.h)
  vec4 caustic_depths;  // depth m of each caustic slice, increasing
  vec4 caustic_share;   // the sun's direct share of the light at each slice's depth (optics/underwater.h)
  vec4 water_volume;    // x = scattering coefficient σ at 550 nm (1/m), y = its phase function's g,
                        // z unused (shafts are a specialisation constant), w = the water's effect along view
                        // rays on (1)
  vec4 underwater_top;  // rgb = target(0, 0) of the underwater tables: the light just under the surface, w
                        // unused
  vec4 wakes;           // the wakes' window (common/wake_fields.glsl): xy = world xz of its corner, z = its
                        // width m, w = its cell size m
  // render.shading's classic modes (common/classic_light.glsl): the water's Blinn-Phong material.
  vec4 classic_ambient;   // rgb = ambient reflectance (of the sky's light), w unused
  vec4 classic_diffuse;   // rgb = diffuse reflectance, w = shininess (the exponent of the highlight)
  vec4 classic_specular;  // rgb = specular reflectance, w unused
  SkyModelGpu sky;        // the sky's radiance by direction (shared/sky_model.h), white units
  vec4 whitecaps;  // x = 1 when the whitecaps are drawn, 0 when render.effects.foam hides them; yzw unused
  vec4 direct;  // x = how many of direct_waves the surface sums (0: the cascades carry the sea), yzw unused
  vec4 submerged_rect;  // screen uv (xy least, zw greatest) that bounds every object drawn under the water
                        // (render/scene_objects.h); empty (x > z) when there is none
  // The waves' transformation over the floor (common/shoaling.glsl): xy = world xz where its profile starts,
  // zw = the grid's axis; and x = its spacing m, y = its columns (along the axis), z = its rows, w = the
  // layer of cascade 0's lattice (cascade c's: w + c).
  vec4 shoaling_axis;
  vec4 shoaling_grid;
  // Per cascade, its representative wave whose phase over the floor moves its lattice
  // (shared/shoaling_math.h): xy = k0 (world xz, rad/m), zw = k0/|k0|² (zeros: not moved).
  vec4 shoaling_lattice[LAGOON_MAX_CASCADES];
  // Models gerstner and sines with their own waves (common/direct_waves.glsl), phases at the frame's time.
  DirectWaveGpu direct_waves[LAGOON_DIRECT_MAX_WAVES];
};

// One point light of the scene's "lights" block (storage buffer, std430).
struct PointLightGpu {
  vec4 position_range;  // xyz metres, w = range (m)
  vec4 colour;          // rgb = colour x intensity (irradiance at 1 m in white units), w = the spot cone's
                        // scale (0: a point light; shared/light_spot.h)
  vec4 spot;  // xyz = the direction a spot light shines (unit), w = its cone's offset (1 for a point)
};
LAGOON_GPU_END

#ifdef __cplusplus
LAGOON_CHECK_SIZE(FrameUniforms, 2928);
LAGOON_CHECK_OFFSET(FrameUniforms, sky, 608);
LAGOON_CHECK_SIZE(PointLightGpu, 48);
LAGOON_CHECK_OFFSET(FrameUniforms, unread, 0);
LAGOON_CHECK_OFFSET(FrameUniforms, screen, 16);
LAGOON_CHECK_OFFSET(FrameUniforms, camera_pos, 160);
LAGOON_CHECK_OFFSET(FrameUniforms, water_deep, 240);
LAGOON_CHECK_OFFSET(FrameUniforms, post2, 384);
LAGOON_CHECK_OFFSET(FrameUniforms, underwater, 432);
#endif
#endif
