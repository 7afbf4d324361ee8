#include "render/frame_uniforms.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ocean/direct_waves.h"
#include "ocean/short_waves.h"
#include "ocean/slope_statistics.h"
#include "optics/colour.h"
#include "render/seafloor.h"
#include "render/sky_light.h"
#include "shared/light_spot.h"

namespace lagoon::render {
namespace {

constexpr float kFoamAlbedo = 0.85f;

// The floor's depth under the camera, where the scene's floor is the procedural slope; 0 (unknown) for none
// and for a mesh floor.
float floor_depth_below(const scene::Scene& scene) {
  if (scene.seafloor.type != scene::SeafloorType::Slope) return 0.0f;
  return std::max(world::slope_depth(scene.seafloor, {scene.camera.position.x, scene.camera.position.z}),
                  0.0f);
}

}  // namespace

OceanShading ocean_shading(const ocean::GpuOcean& ocean) {
  OceanShading out;
  const uint32_t drawn = std::min<uint32_t>(ocean.cascade_count(), LAGOON_MAX_CASCADES);
  double variance = 0;
  for (uint32_t c = 0; c < drawn; ++c) {
    out.cascade_mss[c] = float(ocean::mean_square_slope(ocean.spectra()[c]));
    variance += ocean::height_variance(ocean.spectra()[c]);
  }
  const double sigma = std::sqrt(variance);
  out.significant_height_m = float(4.0 * sigma);
  out.bound = {.horizontal_m = float(6.0 * sigma * ocean.params().choppiness + 1.0),
               .vertical_m = float(6.0 * sigma + 1.0)};
  const double last_k = ocean::cascade_bands(ocean.params())[drawn - 1].k_max;
  // The FFT sea's short waves are Elfouhaily's capillary-gravity spectrum (ocean/short_waves.h), as in the
  // water LUTs' roughness (ocean::sea_slope_moments); the classic models keep their spectrum's tail.
  if (ocean.params().model == ocean::SurfaceModel::Fft) {
    const ocean::SlopeMoments rest = ocean::short_wave_slope_moments(ocean.params(), last_k);
    out.subgrid_mss = float(rest.xx + rest.zz);
  } else {
    out.subgrid_mss =
        float(ocean::spectrum_mean_square_slope(ocean.params(), last_k, ocean::kCapillaryCutoffK));
  }
  out.caustic_mss = caustic_unresolved_mss(ocean, CausticsWindow{}.cell_m);
  return out;
}

float caustic_unresolved_mss(const ocean::GpuOcean& ocean, float cell_m) {
  // The caustic splat samples the cascades filtered to its cell (a mip per cascade): it keeps |k| < π/cell.
  const uint32_t drawn = std::min<uint32_t>(ocean.cascade_count(), LAGOON_MAX_CASCADES);
  const ocean::SlopeMoments unresolved = ocean::unresolved_slope_moments(
      ocean.params(), ocean.spectra(), drawn, std::numbers::pi / double(cell_m));
  return float(unresolved.xx + unresolved.zz);
}

uint32_t write_point_lights(const scene::Scene& scene, const std::vector<scene::PointLight>& more,
                            gpu::PointLightGpu* out) {
  const uint32_t count = uint32_t(std::min<size_t>(scene.lights.size() + more.size(), LAGOON_MAX_LIGHTS));
  for (uint32_t i = 0; i < count; ++i) {
    const scene::PointLight& l = i < scene.lights.size() ? scene.lights[i] : more[i - scene.lights.size()];
    const bool spot = l.spot_outer_deg < 180.f;
    const glm::vec2 cone = spot ? gpu::spot_cone(std::cos(glm::radians(l.spot_inner_deg)),
                                                 std::cos(glm::radians(l.spot_outer_deg)))
                                : glm::vec2(0.0f, 1.0f);
    out[i] = {.position_range = glm::vec4(l.position, l.range_m),
              .colour = glm::vec4(l.colour * l.intensity, cone.x),
              .spot = glm::vec4(glm::normalize(l.spot_direction), cone.y)};
  }
  return count;
}

gpu::FrameUniforms frame_uniforms(const FrameInputs& in) {
  const scene::Scene& scene = in.scene;
  const SkyLight light = sky_light(scene.sun);
  optics::ToneMapParams tone;
  tone.world_adaptation_luminance = scene.render.tone_map_adaptation;
  tone.white_luminance = scene.render.tone_map_white;
  const optics::ToneMapCurve curve = optics::tone_map_curve(tone);
  const float width = float(in.extent.width), height = float(in.extent.height);
  const uint32_t drawn = std::min<uint32_t>(in.ocean.cascade_count(), LAGOON_MAX_CASCADES);
  gpu::FrameUniforms f{
      .screen = glm::vec4(width, height, 1.0f / width, 1.0f / height),
      .view_proj = in.view_proj,
      .inv_view_proj = glm::inverse(in.view_proj),
      .camera_pos = glm::vec4(scene.camera.position, float(scene.time_s)),
      .sun_dir = glm::vec4(light.sun_direction, float(scene.water.ior)),
      .sun_irradiance = glm::vec4(light.sun_irradiance, 0.0f),
      .sky_radiance = glm::vec4(light.sky_radiance, float(std::cos(kSunDiscRadiusRad))),
      .sun_disc = glm::vec4(light.sun_disc_radiance, 0.0f),
      .water_deep = glm::vec4(in.luts.deep_colour, kFoamAlbedo),
      .grid = glm::vec4(in.grid.grid.x, in.grid.grid.y, 0.35f * in.reach_m, float(drawn)),
      .clipmap = in.grid.clipmap,
      .cascade_mss = in.shading.cascade_mss,
      .glint = glm::vec4(in.shading.subgrid_mss, float(in.ocean.foam_rule().whole.onset),
                         scene.render.effects.shore_foam && scene.render.effects.foam
                             ? in.shading.significant_height_m
                             : 0.0f,
                         float(in.ocean.foam_rule().whole.width)),
      .post = glm::vec4(scene.render.exposure, scene.render.gamma, float(curve.m), float(curve.exponent)),
      .post2 = glm::vec4(float(curve.white), float(curve.world_adaptation),
                         scene.render.tone_map == scene::ToneMap::Clamp ? 0.0f : 1.0f, 0.0f),
      .lut = glm::vec4(float(in.luts.r_max_m), float(in.luts.h_max_m),
                       scene.render.effects.refraction ? 1.0f : 0.0f, light.light_scale),
      .lights = glm::vec4(float(in.light_count), 0, 0, 0),
      .underwater =
          glm::vec4(float(in.luts.d_max_m), float(in.luts.z_max_m), in.under_water ? 1.0f : 0.0f, 0),
      .floor_below = glm::vec4(floor_depth_below(scene), float(scene.water.bottom_albedo), 0, 0),
      .caustics = glm::vec4(in.caustics.origin, in.caustics.cell_m, float(in.caustics.cells)),
      .caustic_depths = in.caustics.depths,
      .caustic_share = in.luts.caustic_share,
      .water_volume = glm::vec4(in.luts.scattering_550, in.luts.phase_g_550, 0.0f,
                                scene.render.effects.underwater ? 1.0f : 0.0f),
      .underwater_top = glm::vec4(in.luts.underwater_top, 0.0f),
      .wakes = in.wakes_window,
      .classic_ambient = glm::vec4(scene.render.classic.ambient, 0.0f),
      .classic_diffuse = glm::vec4(scene.render.classic.diffuse, scene.render.classic.shininess),
      .classic_specular = glm::vec4(scene.render.classic.specular, 0.0f),
      .sky = light.sky_model,
      .whitecaps = glm::vec4(scene.render.effects.foam ? 1.0f : 0.0f, 0.0f, 0.0f, 0.0f),
      .submerged_rect = in.submerged_rect,
      .shoaling_axis = in.ocean.shoaling_gpu().axis(),
      .shoaling_grid = in.ocean.shoaling_gpu().grid()};
  for (size_t c = 0; c < LAGOON_MAX_CASCADES; ++c) f.shoaling_lattice[c] = in.ocean.shoaling_gpu().lattice(c);
  if (const ocean::GerstnerSurface* direct = in.ocean.direct_waves()) {
    const std::vector<gpu::DirectWaveGpu> waves = ocean::direct_waves_gpu(*direct, scene.time_s);
    const size_t count = std::min<size_t>(waves.size(), LAGOON_DIRECT_MAX_WAVES);  // validate() keeps to it
    std::copy_n(waves.begin(), count, f.direct_waves);
    f.direct.x = float(count);
  }
  for (uint32_t c = 0; c < drawn; ++c) {
    const ocean::CascadeTextures tex = in.ocean.cascade(c);
    f.cascade_patch[c] = float(tex.patch_size_m);
    f.cascade_layer[c] = float(tex.layer);
    f.cascade_texel[c] = float(tex.patch_size_m / tex.resolution);
  }
  return f;
}

}  // namespace lagoon::render
