#include "ocean/gpu/gpu_ocean.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstring>
#include <optional>
#include <stdexcept>

#include <glm/gtc/packing.hpp>

#include "lagoon_shaders/shaders.h"
#include "ocean/direct_waves.h"
#include "ocean/random_sea.h"
#include "ocean/slope_statistics.h"
#include "ocean/validate.h"
#include "shared/limits.h"
#include "shared/ocean.h"
#include "vk/barriers.h"
#include "vk/check.h"
#include "vk/transfer.h"

namespace lagoon::ocean {

// Cascades that share a resolution are batched through the same passes.
struct GpuOcean::Group {
  uint32_t n = 0;
  std::vector<uint32_t> cascades;
  vk::Buffer spectrum;  // vec4 (h0(k), conj(h0(-k))) per k, cascade after cascade
  vk::Buffer omega;     // float ω(k)
  std::unique_ptr<OceanFftPath> fft;
  // Cascades with nothing to step (an empty spectrum, and no model writing them): cleared to still water
  // once, then left alone (model perlin fills only the first cascade; springs and direct waves only write
  // it).
  bool still = false;
  vk::Image displacement, normal_jacobian, jacobian_terms;
  std::array<const vk::Image*, 3> images() const {
    return {&displacement, &normal_jacobian, &jacobian_terms};
  }
  void upload_spectra(vk::Context& ctx, const std::vector<CascadeSpectrum>& spectra);
  void create_images(vk::Context& ctx);
};

namespace {

// One cascade's layer of the spectrum buffers: `pairs` gets (h0(k), conj(h0(-k))) per texel, so the
// evolution reads both halves of the Hermitian pair at once; `omegas` gets ω(k).
void pack_spectrum(const CascadeSpectrum& s, uint32_t n, float* pairs, float* omegas) {
  for (uint32_t iz = 0; iz < n; ++iz)
    for (uint32_t ix = 0; ix < n; ++ix) {
      const size_t i = size_t{iz} * n + ix, mirrored = size_t{(n - iz) % n} * n + (n - ix) % n;
      float* out = &pairs[i * 4];
      out[0] = s.h0[i].real();
      out[1] = s.h0[i].imag();
      out[2] = s.h0[mirrored].real();  // conj(h0(-k))
      out[3] = -s.h0[mirrored].imag();
      omegas[i] = s.omega[i];
    }
}

}  // namespace

// The group's cascades' spectra, cascade after cascade, uploaded once: they do not change with time.
void GpuOcean::Group::upload_spectra(vk::Context& ctx, const std::vector<CascadeSpectrum>& spectra) {
  const size_t texels = size_t{n} * n;
  std::vector<float> pairs(texels * 4 * cascades.size()), omegas(texels * cascades.size());
  for (size_t layer = 0; layer < cascades.size(); ++layer)
    pack_spectrum(spectra[cascades[layer]], n, &pairs[layer * texels * 4], &omegas[layer * texels]);
  spectrum =
      vk::Buffer::create(ctx, pairs.size() * 4, vk::kStorageUsage, vk::MemoryUsage::Device, "ocean h0");
  omega =
      vk::Buffer::create(ctx, omegas.size() * 4, vk::kStorageUsage, vk::MemoryUsage::Device, "ocean omega");
  vk::upload_buffer(ctx, spectrum, vk::as_bytes_of(pairs));
  vk::upload_buffer(ctx, omega, vk::as_bytes_of(omegas));
}

// The step's outputs, one layer per cascade with full mip chains, left in GENERAL for the compute passes.
void GpuOcean::Group::create_images(vk::Context& ctx) {
  const vk::ImageDesc desc{.format = VK_FORMAT_R32G32B32A32_SFLOAT,
                           .extent = {n, n},
                           .mip_levels = 0,
                           .layers = uint32_t(cascades.size()),
                           .array_view = true,
                           .usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                    VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT};
  vk::ImageDesc d = desc;
  d.debug_name = "ocean displacement";
  displacement = vk::Image::create(ctx, d);
  d.debug_name = "ocean normal+jacobian";
  normal_jacobian = vk::Image::create(ctx, d);
  // Half floats: the terms only decide where foam shows (relative error 5e-4), and half the bytes keep
  // their mips and sampling cheap on CPU devices.
  d.debug_name = "ocean jacobian terms";
  d.format = VK_FORMAT_R16G16B16A16_SFLOAT;
  jacobian_terms = vk::Image::create(ctx, d);
  // Cleared to still water (no displacement, normal up, J = 1, no foam): model springs writes only the first
  // cascade, and the others must read as a flat sea.
  ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    const VkClearColorValue zero{}, up{.float32 = {0.0f, 1.0f, 0.0f, 1.0f}};
    for (const vk::Image* image : images()) {
      const VkImageSubresourceRange range = image->all_subresources();
      vk::image_barrier(cmd, image->handle(), range, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                        vk::access::kNone, vk::access::kTransferWrite);
      vkCmdClearColorImage(cmd, image->handle(), VK_IMAGE_LAYOUT_GENERAL,
                           image == &normal_jacobian ? &up : &zero, 1, &range);
    }
    vk::memory_barrier(cmd, vk::access::kTransferWrite, vk::access::kComputeReadWrite);
  });
}

Result<std::unique_ptr<GpuOcean>> GpuOcean::create(vk::Context& ctx, const OceanParams& params,
                                                   FftVariant variant, FoamRuleSource foam_rule_source) {
  if (auto valid = validate(params); !valid) return valid.error();
  return std::make_unique<GpuOcean>(ctx, params, variant, std::move(foam_rule_source));
}

GpuOcean::GpuOcean(vk::Context& ctx, const OceanParams& params, FftVariant variant,
                   FoamRuleSource foam_rule_source)
    : ctx_(ctx),
      params_(params),
      variant_(variant),
      foam_rule_source_(std::move(foam_rule_source)),
      mips_(vk::ComputePipeline::create(ctx, shaders::ocean_mips_comp)) {
  if (auto valid = validate(params); !valid) throw std::logic_error("GpuOcean: " + valid.error().message);
  std::vector<CascadeSpectrum> spectra = make_cascade_spectra(params);
  build(std::move(spectra));
}

GpuOcean::GpuOcean(vk::Context& ctx, const OceanParams& params, std::vector<CascadeSpectrum> spectra,
                   FftVariant variant)
    : ctx_(ctx),
      params_(params),
      variant_(variant),
      mips_(vk::ComputePipeline::create(ctx, shaders::ocean_mips_comp)) {
  if (spectra.size() != params.cascades.size()) vk::throw_usage_error("GpuOcean: one spectrum per cascade");
  build(std::move(spectra));
}

GpuOcean::~GpuOcean() = default;

const FoamRule& GpuOcean::foam_rule() const {
  if (!foam_rule_)
    foam_rule_ = foam_rule_pending_.valid() ? foam_rule_pending_.get() : ocean::foam_rule(params_, spectra_);
  return *foam_rule_;
}

void GpuOcean::build(std::vector<CascadeSpectrum> spectra) {
  spectra_ = std::move(spectra);
  foam_rule_.reset();
  foam_rule_pending_ =
      std::async(std::launch::async, [source = foam_rule_source_, params = params_, spectra = spectra_] {
        return source ? source(params, spectra) : ocean::foam_rule(params, spectra);
      });
  groups_.clear();
  cascade_slots_.assign(spectra_.size(), {0, 0});
  reset_foam_ = true;
  const std::optional<GerstnerParams> direct = direct_wave_params(params_);
  const bool writes_first = direct || params_.model == SurfaceModel::Springs;
  for (uint32_t c = 0; c < spectra_.size(); ++c) {
    const uint32_t n = spectra_[c].resolution;
    const bool still = !(writes_first && c == 0) &&
                       std::all_of(spectra_[c].h0.begin(), spectra_[c].h0.end(),
                                   [](std::complex<float> h) { return h == std::complex<float>(0.0f); });
    auto it = std::find_if(groups_.begin(), groups_.end(),
                           [&](const auto& g) { return g->n == n && g->still == still; });
    if (it == groups_.end()) {
      groups_.push_back(std::make_unique<Group>());
      groups_.back()->n = n;
      groups_.back()->still = still;
      it = groups_.end() - 1;
    }
    cascade_slots_[c] = {uint32_t(it - groups_.begin()), uint32_t((*it)->cascades.size())};
    (*it)->cascades.push_back(c);
  }
  for (auto& g : groups_) {
    const uint32_t count = uint32_t(g->cascades.size());
    if (count > LAGOON_MAX_CASCADES)
      vk::throw_usage_error("GpuOcean: more cascades than LAGOON_MAX_CASCADES");
    g->upload_spectra(ctx_, spectra_);
    if (!writes_first && !g->still) g->fft = make_ocean_fft_path(ctx_, variant_, g->n, count);
    g->create_images(ctx_);
  }
  springs_ = params_.model == SurfaceModel::Springs ? std::make_unique<SpringsGpu>(ctx_, params_) : nullptr;
  // The waves the surface sums: the model's own (and then their step replaces the FFT's), or swell trains
  // over the cascades.
  const RandomSea sea = random_sea(params_, spectra_);
  const std::optional<GerstnerParams> summed = summed_wave_params(params_, sea);
  direct_surface_ = summed ? std::make_unique<GerstnerSurface>(*summed) : nullptr;
  direct_ = direct ? std::make_unique<DirectWavesGpu>(ctx_, params_, *direct_surface_) : nullptr;
  // The summed waves' table holds the random sea's scale too.
  shoaling_ = direct_surface_ ? direct_surface_->shared_shoaling() : ocean::sea_over_floor(params_, sea);
  shoaling_gpu_ = std::make_unique<ShoalingGpu>(ctx_, shoaling_.get());
}

void GpuOcean::record_step(VkCommandBuffer cmd, double time_s, double dt_s, vk::GpuTimer* timer, Step step,
                           bool build_foam) {
  // Readers of last step's textures (graphics sampling, readback) must finish before they are rewritten.
  const vk::Access readers{vk::access::kGraphicsSampled.stage | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT |
                               VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                           vk::access::kGraphicsSampled.access | VK_ACCESS_2_SHADER_STORAGE_READ_BIT |
                               VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT};
  for (auto& g : groups_) {
    if (g->still) continue;
    const uint32_t n = g->n, count = uint32_t(g->cascades.size());
    gpu::OceanPush push{.patch_size_m = {},
                        .cascades = count,
                        .reset_foam = reset_foam_ ? 1u : 0u,
                        .time_s = float(time_s),
                        .dt_s = float(dt_s),
                        .choppiness = float(params_.choppiness),
                        .foam_build = build_foam ? 1.0f : 0.0f,
                        .foam_decay_per_s = float(params_.foam.decay_per_s)};
    for (uint32_t layer = 0; layer < count; ++layer) {
      push.patch_size_m[layer] = float(spectra_[g->cascades[layer]].patch_size_m);
      const FoamRamp& foam = foam_rule().cascades[g->cascades[layer]];
      push.foam_onset[layer] = float(foam.onset);
      push.foam_width[layer] = float(foam.width);
    }

    // The previous step (possibly in the same command buffer) may still read the FFT buffers.
    vk::memory_barrier(cmd, vk::access::kComputeReadWrite, vk::access::kComputeReadWrite);
    for (const vk::Image* image : g->images())
      vk::image_barrier(cmd, image->handle(), image->all_subresources(), VK_IMAGE_LAYOUT_GENERAL,
                        VK_IMAGE_LAYOUT_GENERAL, readers, vk::access::kComputeReadWrite);
    const LayerTarget first{&g->displacement, &g->normal_jacobian, &g->jacobian_terms,
                            cascade_slots_[0].second};
    const bool holds_first = g.get() == groups_[cascade_slots_[0].first].get();
    if (springs_) {
      if (holds_first) springs_->record(cmd, time_s, dt_s, reset_foam_, first, timer);
    } else if (direct_) {
      if (holds_first) direct_->record(cmd, time_s, dt_s, reset_foam_, first, timer);
    } else {
      g->fft->record(cmd,
                     {&g->spectrum, &g->omega, &g->displacement, &g->normal_jacobian, &g->jacobian_terms},
                     push, timer, step == Step::WarmUp ? StepOutputs::FoamOnly : StepOutputs::All);
    }
    if (step == Step::Full) {
      vk::GpuScope scope(timer, cmd, "ocean mips " + std::to_string(n));
      // Level by level, each from the one above; the three textures in one dispatch per level.
      // None for a direct sum: the renderer samples no cascade of it.
      const uint32_t levels = direct_ ? 1 : g->displacement.mip_levels();
      for (uint32_t mip = 1; mip < levels; ++mip) {
        vk::memory_barrier(cmd, vk::access::kComputeWrite, vk::access::kComputeRead);
        auto level = [&](const vk::Image& image, uint32_t m) {
          return vk::ImageRef{image.mip_view(m), VK_IMAGE_LAYOUT_GENERAL};
        };
        const uint32_t size = std::max(n >> mip, 1u);
        vk::dispatch(cmd, mips_,
                     {vk::bind(LAGOON_MIPS_BIND_SRC + 0, level(g->displacement, mip - 1)),
                      vk::bind(LAGOON_MIPS_BIND_SRC + 1, level(g->normal_jacobian, mip - 1)),
                      vk::bind(LAGOON_MIPS_BIND_SRC + 2, level(g->jacobian_terms, mip - 1)),
                      vk::bind(LAGOON_MIPS_BIND_DST + 0, level(g->displacement, mip)),
                      vk::bind(LAGOON_MIPS_BIND_DST + 1, level(g->normal_jacobian, mip)),
                      vk::bind(LAGOON_MIPS_BIND_DST + 2, level(g->jacobian_terms, mip))},
                     vk::groups_for(mips_, {size, size, count}));
      }
      vk::memory_barrier(cmd, vk::access::kComputeWrite, readers);
    }
  }
  reset_foam_ = false;
}

CascadeTextures GpuOcean::cascade(uint32_t index) const {
  const auto [group, layer] = cascade_slots_.at(index);
  const Group& g = *groups_[group];
  return {&g.displacement, &g.normal_jacobian, &g.jacobian_terms, layer, g.n, spectra_[index].patch_size_m};
}

CascadeReadback GpuOcean::read_cascade(uint32_t index) const {
  const CascadeTextures t = cascade(index);
  const vk::Access writer{VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT};
  CascadeReadback out;
  out.resolution = t.resolution;
  const size_t layer_floats = size_t{t.resolution} * t.resolution * 4;
  for (auto [image, target] :
       {std::pair{t.displacement, &out.displacement}, {t.normal_jacobian, &out.normal_jacobian}}) {
    const std::vector<std::byte> bytes = vk::readback_image(ctx_, *image, VK_IMAGE_LAYOUT_GENERAL, writer);
    target->resize(layer_floats);
    std::memcpy(target->data(), bytes.data() + layer_floats * 4 * t.layer, layer_floats * 4);
  }
  // Half floats, widened.
  const std::vector<std::byte> halves =
      vk::readback_image(ctx_, *t.jacobian_terms, VK_IMAGE_LAYOUT_GENERAL, writer);
  out.jacobian_terms.resize(layer_floats);
  for (size_t i = 0; i < layer_floats; ++i) {
    uint16_t h = 0;
    std::memcpy(&h, halves.data() + (layer_floats * t.layer + i) * 2, 2);
    out.jacobian_terms[i] = glm::unpackHalf1x16(h);
  }
  return out;
}

std::vector<float> GpuOcean::read_foam() const {
  const vk::Access writer{VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT};
  std::vector<float> foam;
  std::vector<std::vector<float>> texels(groups_.size());  // each group's layers, read once
  for (size_t g = 0; g < groups_.size(); ++g) {
    const std::vector<std::byte> bytes =
        vk::readback_image(ctx_, groups_[g]->displacement, VK_IMAGE_LAYOUT_GENERAL, writer);
    texels[g].resize(bytes.size() / sizeof(float));
    std::memcpy(texels[g].data(), bytes.data(), texels[g].size() * sizeof(float));
  }
  for (const auto& [group, layer] : cascade_slots_) {
    const size_t n2 = size_t{groups_[group]->n} * groups_[group]->n;
    const float* rgba = texels[group].data() + 4 * n2 * layer;
    for (size_t i = 0; i < n2; ++i) foam.push_back(rgba[4 * i + 3]);
  }
  return foam;
}

bool GpuOcean::write_foam(std::span<const float> foam) {
  size_t total = 0;
  for (const auto& [group, layer] : cascade_slots_) total += size_t{groups_[group]->n} * groups_[group]->n;
  if (springs_ || foam.size() != total) return false;
  std::vector<std::vector<float>> texels(groups_.size());
  for (size_t g = 0; g < groups_.size(); ++g)
    texels[g].assign(4 * size_t{groups_[g]->n} * groups_[g]->n * groups_[g]->cascades.size(), 0.0f);
  size_t at = 0;
  for (const auto& [group, layer] : cascade_slots_) {
    const size_t n2 = size_t{groups_[group]->n} * groups_[group]->n;
    float* rgba = texels[group].data() + 4 * n2 * layer;
    for (size_t i = 0; i < n2; ++i) rgba[4 * i + 3] = foam[at++];
  }
  const vk::Access next{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
  for (size_t g = 0; g < groups_.size(); ++g)
    vk::upload_image(ctx_, groups_[g]->displacement, std::as_bytes(std::span(texels[g])),
                     VK_IMAGE_LAYOUT_GENERAL, next);
  reset_foam_ = false;
  return true;
}

}  // namespace lagoon::ocean
