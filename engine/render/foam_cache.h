// A still frame's foam warm-up (OceanStepPass::prepare: 3 s of steps, ~1 s on lavapipe at the shipped
// cascades) kept between runs in the result cache (io/result_cache.h): a second render of the same sea at the
// same time on the same device starts from the foam the first one built, bit for bit the state its own
// warm-up would have left. The key holds everything the steps compute from: the code's fingerprint, the
// device and driver (another device rounds differently; on a CPU device, the host's instruction set too),
// the FFT variant, each cascade's h0(k) and ω(k), the step's parameters, the frame's time and the warm-up's
// steps.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "io/result_cache.h"
#include "ocean/gpu/gpu_ocean.h"
#include "vk/context.h"

namespace lagoon::render {

struct WarmUp {
  double time_s = 0;    // of the frame
  double length_s = 0;  // run before it
  double step_s = 0;    // in steps of
};

// The digest of every cascade's h0(k) and ω(k) (2.4 MB at the shipped cascades: once per ocean, not per
// frame).
std::string spectra_digest(const ocean::GpuOcean& ocean);

io::ResultKey foam_key(const vk::Context& ctx, const ocean::GpuOcean& ocean,
                       const std::string& spectra_digest, const WarmUp& warm_up);

// The foam rule (ocean/whitecaps.h) for these parameters and spectra, as an earlier run worked it out (~0.3 s
// of CPU FFTs at the shipped cascades, on the thread GpuOcean gives it), or worked out and filed now: a
// GpuOcean's FoamRuleSource.
ocean::FoamRule cached_foam_rule(const ocean::OceanParams& params,
                                 const std::vector<ocean::CascadeSpectrum>& spectra);

// The foam an earlier run filed under `key`, when there is one that fits `ocean`.
std::optional<std::vector<float>> load_foam(const io::ResultKey& key, const ocean::GpuOcean& ocean);
void store_foam(const io::ResultKey& key, const std::vector<float>& foam);

}  // namespace lagoon::render
