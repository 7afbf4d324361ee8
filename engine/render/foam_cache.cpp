#include "render/foam_cache.h"

#include <span>
#include <string>

#include "io/sha256.h"
#include "render/cached_tables.h"
#include "render/device_key.h"

namespace lagoon::render {

std::string spectra_digest(const std::vector<ocean::CascadeSpectrum>& spectra) {
  std::string all;
  for (const ocean::CascadeSpectrum& s : spectra) {
    all += io::sha256_hex(std::as_bytes(std::span(s.h0))) + "\n";
    all += io::sha256_hex(std::as_bytes(std::span(s.omega))) + "\n";
  }
  return io::sha256_hex(std::as_bytes(std::span(all.data(), all.size())));
}

std::string spectra_digest(const ocean::GpuOcean& ocean) {
  return spectra_digest(ocean.spectra());
}

ocean::FoamRule cached_foam_rule(const ocean::OceanParams& p,
                                 const std::vector<ocean::CascadeSpectrum>& spectra) {
  io::ResultKey key = table_key("whitecaps");
  key.add("model", double(int(p.model))).add("coverage", double(int(p.foam.coverage)));
  key.add("threshold", p.foam.threshold).add("decay", p.foam.decay_per_s).add("choppiness", p.choppiness);
  key.add("wind", p.spectrum.wind_speed_mps);
  for (const ocean::CascadeSpectrum& s : spectra)
    key.add("resolution", s.resolution).add("patch_size", s.patch_size_m);
  key.add("spectra", spectra_digest(spectra));
  const size_t count = 2 + 2 * spectra.size();
  const io::ResultCache cache = io::ResultCache::from_environment();
  if (auto v = cache.load_vector<double>(key, count)) {
    ocean::FoamRule rule{{(*v)[0], (*v)[1]}, {}};
    for (size_t c = 0; c < spectra.size(); ++c) rule.cascades.push_back({(*v)[2 + 2 * c], (*v)[3 + 2 * c]});
    return rule;
  }
  const ocean::FoamRule rule = ocean::foam_rule(p, spectra);
  std::vector<double> values = {rule.whole.onset, rule.whole.width};
  for (const ocean::FoamRamp& c : rule.cascades) values.push_back(c.onset), values.push_back(c.width);
  cache.store_vector(key, values);
  return rule;
}

io::ResultKey foam_key(const vk::Context& ctx, const ocean::GpuOcean& ocean,
                       const std::string& spectra_digest, const WarmUp& warm_up) {
  const ocean::OceanParams& p = ocean.params();
  io::ResultKey key = table_key("foam");
  add_device(key, ctx);
  key.add("variant", double(int(ocean.variant()))).add("model", double(int(p.model)));
  key.add("choppiness", float(p.choppiness)).add("foam_threshold", float(p.foam.threshold));
  // The cascades' onsets follow the coverage rule (ocean/whitecaps.h), Monahan's from the wind.
  key.add("foam_coverage", double(int(p.foam.coverage))).add("wind", float(p.spectrum.wind_speed_mps));
  key.add("foam_decay", float(p.foam.decay_per_s));
  for (const ocean::CascadeSpectrum& s : ocean.spectra())
    key.add("resolution", s.resolution).add("patch_size", float(s.patch_size_m));
  key.add("spectra", spectra_digest);
  key.add("time", warm_up.time_s).add("length", warm_up.length_s).add("step", warm_up.step_s);
  return key;
}

std::optional<std::vector<float>> load_foam(const io::ResultKey& key, const ocean::GpuOcean& ocean) {
  size_t texels = 0;
  for (const ocean::CascadeSpectrum& s : ocean.spectra()) texels += size_t{s.resolution} * s.resolution;
  return io::ResultCache::from_environment().load_vector<float>(key, texels);
}

void store_foam(const io::ResultKey& key, const std::vector<float>& foam) {
  // Fewer than the other kinds: 0.8 MB each at the shipped cascades (25 MB in all), and every frame of a
  // dataset is another time.
  constexpr size_t kKept = 32;
  io::ResultCache::from_environment().store_vector(key, foam, kKept);
}

}  // namespace lagoon::render
