#include "support/particle_candidates.h"

#include "lagoon_test_shaders/shaders.h"
#include "render/passes/particles_pass.h"
#include "support/vk_fixture.h"
#include "vk/barriers.h"
#include "vk/pipeline.h"
#include "vk/transfer.h"

namespace lagoon::test {

std::vector<glm::vec4> particle_candidates(vk::Context& ctx, const scene::Scene& scene) {
  const gpu::ParticlesPush push = render::particles_push(scene);
  vk::Buffer out = vk::Buffer::create(ctx, kParticleCandidates * sizeof(glm::vec4),
                                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                      vk::MemoryUsage::Device, "candidates");
  const vk::ComputePipeline eval = vk::ComputePipeline::create(ctx, shaders::gpu_particles_eval_comp);
  ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    vk::dispatch(cmd, eval, {vk::bind(0, out)}, push, vk::groups_for(eval, {kParticleCandidates, 1, 1}));
    vk::memory_barrier(cmd, vk::access::kComputeWrite, vk::access::kTransferRead);
  });
  return from_bytes<glm::vec4>(vk::readback_buffer(ctx, out));
}

}  // namespace lagoon::test
