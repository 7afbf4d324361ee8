#include "render/water_luts.h"

#include <optional>
#include <vector>

#include "io/result_cache.h"
#include "io/sha256.h"
#include "ocean/slope_statistics.h"
#include "optics/lut.h"
#include "optics/underwater.h"
#include "render/cached_tables.h"
#include "render/passes/caustics_pass.h"
#include "vk/barriers.h"
#include "vk/transfer.h"

namespace lagoon::render {

namespace {

vk::Image upload_rgba(vk::Context& ctx, uint32_t width, uint32_t height, const std::vector<float>& data,
                      const char* name) {
  vk::Image image =
      vk::Image::create(ctx, {.format = VK_FORMAT_R32G32B32A32_SFLOAT,
                              .extent = {width, height},
                              .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                              .debug_name = name});
  vk::upload_image(ctx, image, vk::as_bytes_of(data), VK_IMAGE_LAYOUT_GENERAL, vk::access::kGraphicsSampled);
  return image;
}

// A table stored [x][y][channels] as an RGBA image with x along rows (alpha 1 where it has 3 channels).
std::vector<float> as_rgba(const std::vector<float>& table, uint32_t nx, uint32_t ny, uint32_t channels) {
  std::vector<float> out(size_t{nx} * ny * 4, 1.0f);
  for (uint32_t j = 0; j < ny; ++j)
    for (uint32_t i = 0; i < nx; ++i)
      for (uint32_t c = 0; c < channels; ++c)
        out[(size_t{j} * nx + i) * 4 + c] = table[(size_t{i} * ny + j) * channels + c];
  return out;
}

// What the renderer takes from the optics model: the colour LUT, the underwater tables and a few scalars.
// Computed on the CPU (slope statistics ~25 ms, the wavy surface's coefficients ~80 ms, the tables ~20 ms),
// so kept in the result cache (render/cached_tables.h) under every input they come from.
struct WaterTables {
  optics::WaterLut lut;
  optics::UnderwaterTable underwater;
  float scattering_550 = 0, phase_g_550 = 0;
  glm::vec4 caustic_share{0};
};

Result<WaterTables> compute_water_tables(const optics::LutInputs& inputs) {
  WaterTables t;
  auto lut = optics::build_water_lut(inputs);
  if (!lut) return lut.error();
  t.lut = std::move(*lut);
  auto table = optics::build_underwater_table(inputs);
  if (!table) return table.error();
  t.underwater = std::move(*table);
  const int green = optics::sample_index(550);
  t.scattering_550 = float(inputs.water.scattering_per_m[green]);
  t.phase_g_550 = float(optics::phase_x1_at(inputs, green) / 3.0);
  const glm::vec4 depths = CausticsWindow{}.depths;
  for (int k = 0; k < LAGOON_CAUSTICS_SLICES; ++k) {
    auto sample = optics::underwater_sample(inputs, 0.0, depths[k]);
    if (!sample) return sample.error();
    t.caustic_share[k] = float(sample->direct_share);
  }
  return t;
}

std::vector<std::byte> serialise(const WaterTables& t) {
  io::ByteWriter out;
  out.put(t.lut.r_count), out.put(t.lut.h_count), out.put(t.lut.deep_colour);
  out.put_vector(t.lut.r_m), out.put_vector(t.lut.h_m), out.put_vector(t.lut.t0), out.put_vector(t.lut.t1);
  const optics::UnderwaterTable& u = t.underwater;
  out.put(u.d_count), out.put(u.z_count), out.put(u.kd_luminance_per_m);
  out.put_vector(u.d_m), out.put_vector(u.z_m);
  out.put_vector(u.target), out.put_vector(u.water_down), out.put_vector(u.water_up);
  out.put(t.scattering_550), out.put(t.phase_g_550), out.put(t.caustic_share);
  return out.bytes();
}

// nullopt for bytes that are not a whole set of tables with consistent sizes.
std::optional<WaterTables> deserialise(std::span<const std::byte> bytes) {
  constexpr size_t kMax = 1u << 24;  // far above any table a scene may ask for
  io::ByteReader in(bytes);
  WaterTables t;
  t.lut.r_count = in.get<uint32_t>(), t.lut.h_count = in.get<uint32_t>();
  t.lut.deep_colour = in.get<glm::dvec3>();
  t.lut.r_m = in.get_vector<double>(kMax), t.lut.h_m = in.get_vector<double>(kMax);
  t.lut.t0 = in.get_vector<float>(kMax), t.lut.t1 = in.get_vector<float>(kMax);
  optics::UnderwaterTable& u = t.underwater;
  u.d_count = in.get<uint32_t>(), u.z_count = in.get<uint32_t>();
  u.kd_luminance_per_m = in.get<double>();
  u.d_m = in.get_vector<double>(kMax), u.z_m = in.get_vector<double>(kMax);
  u.target = in.get_vector<float>(kMax), u.water_down = in.get_vector<float>(kMax);
  u.water_up = in.get_vector<float>(kMax);
  t.scattering_550 = in.get<float>(), t.phase_g_550 = in.get<float>();
  t.caustic_share = in.get<glm::vec4>();
  const size_t lut_n = size_t{t.lut.r_count} * t.lut.h_count, uw_n = size_t{u.d_count} * u.z_count;
  if (!in.complete() || t.lut.r_m.size() != t.lut.r_count || t.lut.h_m.size() != t.lut.h_count ||
      t.lut.t0.size() != 4 * lut_n || t.lut.t1.size() != 3 * lut_n || u.d_m.size() != u.d_count ||
      u.z_m.size() != u.z_count || u.target.size() != 4 * uw_n || u.water_down.size() != 3 * uw_n ||
      u.water_up.size() != 3 * uw_n)
    return std::nullopt;
  return t;
}

// Everything the tables are computed from: the water block, the water's own table when it is a custom one
// (its contents), the sun's elevation and the sea's slope statistics.
Result<io::ResultKey> water_key(const scene::Scene& scene, const ocean::SlopeMoments& m) {
  static_assert(sizeof(optics::WaterParams) == 160, "a new water parameter must join the tables' key");
  const optics::WaterParams& w = scene.water;
  io::ResultKey key = table_key("water");
  key.add("type", w.type).add("phase", w.phase).add("bottom_albedo", w.bottom_albedo);
  key.add("phase_x1", w.phase_x1).add("lut_gamma", w.lut_gamma).add("diffuse_path", w.diffuse_path_factor);
  key.add("ior", w.ior).add("lut_size", w.lut_size).add("lut_r_max", w.lut_r_max_m);
  key.add("lut_h_max", w.lut_h_max_m);
  if (w.type == "custom") {
    Result<std::string> table = io::sha256_file(w.table);
    if (!table) return table.error();
    key.add("table_sha256", *table);
  }
  key.add("sun_elevation", scene.sun.elevation_deg).add("slope_xx", m.xx).add("slope_zz", m.zz);
  key.add("slope_xz", m.xz);
  return key;
}

Result<WaterTables> water_tables(const scene::Scene& scene,
                                 const std::vector<ocean::CascadeSpectrum>* spectra) {
  const ocean::SlopeMoments m =
      spectra ? ocean::sea_slope_moments(scene.ocean, *spectra) : ocean::sea_slope_moments(scene.ocean);
  Result<io::ResultKey> key = water_key(scene, m);
  const io::ResultCache cache = io::ResultCache::from_environment();
  if (key)
    if (auto bytes = cache.load(*key))
      if (std::optional<WaterTables> cached = deserialise(*bytes)) return std::move(*cached);
  auto inputs =
      optics::lut_inputs(scene.water, scene.sun.elevation_deg, {}, {.xx = m.xx, .zz = m.zz, .xz = m.xz});
  if (!inputs) return inputs.error();
  Result<WaterTables> tables = compute_water_tables(*inputs);
  if (tables && key) cache.store(*key, serialise(*tables));
  return tables;
}

}  // namespace

Result<optics::LutInputs> scene_lut_inputs(const scene::Scene& scene,
                                           const std::vector<ocean::CascadeSpectrum>* spectra) {
  const ocean::SlopeMoments m =
      spectra ? ocean::sea_slope_moments(scene.ocean, *spectra) : ocean::sea_slope_moments(scene.ocean);
  return optics::lut_inputs(scene.water, scene.sun.elevation_deg, {}, {.xx = m.xx, .zz = m.zz, .xz = m.xz});
}

Result<WaterLuts> upload_water_luts(vk::Context& ctx, const scene::Scene& scene,
                                    const std::vector<ocean::CascadeSpectrum>* spectra) {
  Result<WaterTables> tables = water_tables(scene, spectra);
  if (!tables) return tables.error();
  const optics::WaterLut& lut = tables->lut;
  WaterLuts out{.deep_colour = glm::vec3(lut.deep_colour),
                .r_max_m = scene.water.lut_r_max_m,
                .h_max_m = scene.water.lut_h_max_m};
  const uint32_t rn = lut.r_count, hn = lut.h_count;
  out.t0 = upload_rgba(ctx, rn, hn, as_rgba(lut.t0, rn, hn, 4), "lut T0");
  out.t1 = upload_rgba(ctx, rn, hn, as_rgba(lut.t1, rn, hn, 3), "lut T1");
  const optics::UnderwaterTable& u = tables->underwater;
  const uint32_t dn = u.d_count, zn = u.z_count;
  out.uw_target = upload_rgba(ctx, dn, zn, as_rgba(u.target, dn, zn, 4), "underwater target");
  out.underwater_top = glm::vec3(u.target[0], u.target[1], u.target[2]);
  out.uw_down = upload_rgba(ctx, dn, zn, as_rgba(u.water_down, dn, zn, 3), "underwater water down");
  out.uw_up = upload_rgba(ctx, dn, zn, as_rgba(u.water_up, dn, zn, 3), "underwater water up");
  out.scattering_550 = tables->scattering_550;
  out.phase_g_550 = tables->phase_g_550;
  out.d_max_m = u.d_m.back();
  out.z_max_m = u.z_m.back();
  out.caustic_share = tables->caustic_share;
  return out;
}

}  // namespace lagoon::render
