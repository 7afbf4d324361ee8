// The FFT ocean's per-frame GPU work (model springs: its grid's step instead, springs_gpu.h; models with
// their own waves: their sum at the first cascade's texels, direct_waves_gpu.h). Once per
// parameter change the CPU computes h0(k) and ω(k) (initial_spectrum.h) and uploads them; every step records,
// per group of cascades sharing a resolution, evolve -> inverse FFT of 4 packed fields -> assembly
// (ocean_fft_path.h: two variants, one per device kind) writing per cascade (one array layer each)
// displacement (λDx, h, λDz, foam) and (normal, Jacobian) textures, then their mip chains. Records only; the
// caller submits.
#pragma once
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "core/result.h"
#include "ocean/gpu/direct_waves_gpu.h"
#include "ocean/gpu/ocean_fft_path.h"
#include "ocean/gpu/shoaling_gpu.h"
#include "ocean/gpu/springs_gpu.h"
#include "ocean/initial_spectrum.h"
#include "ocean/ocean_params.h"
#include "ocean/whitecaps.h"
#include "vk/context.h"
#include "vk/gpu_timer.h"
#include "vk/image.h"
#include "vk/pipeline.h"

namespace lagoon::ocean {

// Where one cascade's textures live.
struct CascadeTextures {
  const vk::Image* displacement = nullptr;     // RGBA32F array: (λDx, h, λDz, foam), metres
  const vk::Image* normal_jacobian = nullptr;  // RGBA32F array: (nx, ny, nz, J)
  // RGBA16F array: (λ∂Dx/∂x, λ∂Dz/∂z, λ∂Dx/∂z, foam). Summed over cascades the terms give the whole sea's
  // Jacobian, which no single cascade's J shows; foam repeats displacement.w for the surface shader.
  const vk::Image* jacobian_terms = nullptr;
  uint32_t layer = 0;
  uint32_t resolution = 0;
  double patch_size_m = 0;
};

// Host copy of one cascade's outputs (mip 0), row-major [z][x], 4 floats per texel.
struct CascadeReadback {
  uint32_t resolution = 0;
  std::vector<float> displacement;
  std::vector<float> normal_jacobian;
  std::vector<float> jacobian_terms;  // from half floats
};

// Where the foam rule comes from: ocean::foam_rule by default; the renderer's keeps it between runs
// (render/foam_cache.h). Called on another thread.
using FoamRuleSource = std::function<FoamRule(const OceanParams&, const std::vector<CascadeSpectrum>&)>;

class GpuOcean {
 public:
  // The way in for parameters a user gave: invalid ones (ocean/validate.h) come back as the error.
  static Result<std::unique_ptr<GpuOcean>> create(vk::Context& ctx, const OceanParams& params,
                                                  FftVariant variant = FftVariant::Auto,
                                                  FoamRuleSource foam_rule_source = {});
  // For parameters known to be valid (tests, tools that validated them): invalid ones are a programming
  // error and throw std::logic_error.
  GpuOcean(vk::Context& ctx, const OceanParams& params, FftVariant variant = FftVariant::Auto,
           FoamRuleSource foam_rule_source = {});
  // For tests: explicit spectra (one per cascade of `params`) instead of make_cascade_spectrum.
  GpuOcean(vk::Context& ctx, const OceanParams& params, std::vector<CascadeSpectrum> spectra,
           FftVariant variant = FftVariant::Auto);
  ~GpuOcean();
  GpuOcean(const GpuOcean&) = delete;
  GpuOcean& operator=(const GpuOcean&) = delete;

  // Records the step to `time_s`; `dt_s` is the time since the previous step (foam decay). The first step
  // after construction starts foam from zero. Textures are ready for fragment/vertex/compute sampling
  // (GENERAL layout) when the command buffer completes. A WarmUp step brings only the foam to its time (the
  // FFT may transform just the two fields the Jacobian needs: half the work on lavapipe) and leaves the mip
  // levels, the rest of the displacement and the other textures for the next Full step, which rewrites them:
  // for steps nobody samples, such as a foam warm-up. Full and warm-up steps give the same foam.
  enum class Step { Full, WarmUp };
  // build_foam false: the FFT ocean's foam only fades in this step (OceanStepPass makes foam at fixed
  // 0.1 s ticks only, so that how often a run steps does not change its foam).
  void record_step(VkCommandBuffer cmd, double time_s, double dt_s, vk::GpuTimer* timer = nullptr,
                   Step step = Step::Full, bool build_foam = true);

  // The next step starts foam from none again, as the first step does, so the foam depends only on the steps
  // recorded from here on (a replayed warm-up, docs/datasets.md). The springs' grid needs no restart: it is
  // always stepped from t = 0 at its fixed step.
  void restart() { reset_foam_ = true; }

  const OceanParams& params() const { return params_; }
  FftVariant variant() const { return variant_; }  // as asked for (Auto: the device kind decides)
  const std::vector<CascadeSpectrum>& spectra() const { return spectra_; }
  // Where the sea whitens (ocean/whitecaps.h), from the parameters and the spectra: each cascade's foam in
  // the steps, and the whole sea's Jacobian's in the surface shader.
  const FoamRule& foam_rule() const;
  CascadeTextures cascade(uint32_t index) const;
  uint32_t cascade_count() const { return uint32_t(params_.cascades.size()); }
  // The waves the surface sums where it is drawn (ocean/direct_waves.h): the model's own (then the renderer
  // samples no cascade at all), swell trains over the cascades, or null.
  const GerstnerSurface* direct_waves() const { return direct_surface_.get(); }
  // The waves' transformation over the scene's floor (ocean/shoaling.h; the direct waves' own, or the random
  // sea's depth-limited height), null where nothing changes; and its table for the shaders.
  const Shoaling* shoaling() const { return shoaling_.get(); }
  const ShoalingGpu& shoaling_gpu() const { return *shoaling_gpu_; }

  // Reads back mip 0 of one cascade (submits and waits; for tests, export and probes).
  CascadeReadback read_cascade(uint32_t index) const;

  // The foam the next step decays (displacement.w), every cascade's N² texels in cascade order; submits and
  // waits. With write_foam, lets a renderer keep a warm-up's result between runs (render/foam_cache.h).
  std::vector<float> read_foam() const;
  // Makes `foam` (laid out as read_foam gives it) the previous step's foam, as if the steps that made it had
  // just run: the next step decays it instead of starting from none. The displacement's other channels and
  // the mips are left for the next Full step, which rewrites them. False, changing nothing, when the size
  // does not fit the cascades (or for model springs, whose state is its grid).
  bool write_foam(std::span<const float> foam);

 private:
  struct Group;
  void build(std::vector<CascadeSpectrum> spectra);

  vk::Context& ctx_;
  OceanParams params_;
  FftVariant variant_;
  std::vector<CascadeSpectrum> spectra_;
  FoamRuleSource foam_rule_source_;
  // Worked out on another thread from build() (~0.3 s of CPU FFTs at the shipped cascades) while the
  // device is set up; taken at the first step or foam_rule().
  mutable std::future<FoamRule> foam_rule_pending_;
  mutable std::optional<FoamRule> foam_rule_;
  std::vector<std::unique_ptr<Group>> groups_;
  std::vector<std::pair<uint32_t, uint32_t>> cascade_slots_;  // cascade -> (group, layer)
  bool reset_foam_ = true;
  vk::ComputePipeline mips_;             // shaders/ocean/mips.comp: a mip level of a group's three textures
  std::unique_ptr<SpringsGpu> springs_;  // model springs: writes the first cascade in place of the FFT
  std::unique_ptr<GerstnerSurface> direct_surface_;  // models with their own waves: the sum ...
  std::unique_ptr<DirectWavesGpu> direct_;           // ... and its step, in place of the FFT
  std::shared_ptr<const Shoaling> shoaling_;
  std::unique_ptr<ShoalingGpu> shoaling_gpu_;
};

}  // namespace lagoon::ocean
