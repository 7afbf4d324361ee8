#include "render/passes/caustics_pass.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>

#include "lagoon_shaders/shaders.h"
#include "render/surface_fields.h"
#include "shared/limits.h"
#include "shared/surface.h"
#include "vk/barriers.h"
#include "vk/transfer.h"

namespace lagoon::render {
namespace {

constexpr size_t kMapTexels = size_t{LAGOON_CAUSTICS_SLICES} * LAGOON_CAUSTICS_CELLS * LAGOON_CAUSTICS_CELLS;

}  // namespace

CausticsPass::CausticsPass(vk::Context& ctx, const SurfaceFields& fields, const Samplers& samplers)
    : fields_(fields),
      samplers_(samplers),
      splat_(vk::ComputePipeline::create(ctx, shaders::caustics_splat_comp,
                                         with_surface_field_specs({}, fields))),
      blur_rows_(vk::ComputePipeline::create(ctx, shaders::caustics_blur_rows_comp)),
      resolve_(vk::ComputePipeline::create(ctx, shaders::caustics_resolve_comp)),
      accum_(vk::Buffer::create(ctx, kMapTexels * sizeof(uint32_t),
                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                vk::MemoryUsage::Device, "caustics accumulation")),
      rows_(vk::Buffer::create(ctx, kMapTexels * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                               vk::MemoryUsage::Device, "caustics rows")),
      map_(vk::Image::create(ctx, {.format = VK_FORMAT_R32_SFLOAT,
                                   .extent = {LAGOON_CAUSTICS_CELLS, LAGOON_CAUSTICS_CELLS},
                                   .layers = LAGOON_CAUSTICS_SLICES,
                                   .array_view = true,
                                   .usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                            VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                   .debug_name = "caustic map"})) {
  // Each frame leaves the accumulation cleared for the next; it starts cleared, and the map at 1.
  vk::upload_buffer(ctx, accum_, vk::as_bytes_of(std::vector<uint32_t>(kMapTexels, 0u)));
  vk::upload_image(ctx, map_, vk::as_bytes_of(std::vector<float>(kMapTexels, 1.0f)), VK_IMAGE_LAYOUT_GENERAL,
                   vk::access::kGraphicsSampled);
}

void CausticsPass::record(const FrameContext& frame, const CausticsWindow& window) const {
  if (window.cells == 0) return;
  vk::GpuScope scope(frame.timer(), frame.cmd, "caustics");
  std::vector<vk::Binding> splat{vk::bind(LAGOON_CAUSTICS_BIND_FRAME, frame.uniforms()),
                                 vk::bind(LAGOON_CAUSTICS_BIND_ACCUM, accum_)};
  // The surface shaders' cascade slots (shared/caustics.h names them the same), without the Jacobian terms,
  // and the wakes.
  for (const vk::Binding& b : surface_field_bindings(fields_, samplers_))
    if (b.binding != LAGOON_SURFACE_BIND_JACOBIAN_TERMS) splat.push_back(b);
  const gpu::CausticsPush push{
      .source = glm::vec4(window.source_origin, float(window.source_cells.x), float(window.source_cells.y))};
  vk::dispatch(frame.cmd, splat_, splat, &push, sizeof(push),
               vk::groups_for(splat_, {window.source_cells.x * LAGOON_CAUSTICS_RAYS,
                                       window.source_cells.y * LAGOON_CAUSTICS_RAYS, 1}));
  vk::buffer_barrier(frame.cmd, accum_.handle(), vk::access::kComputeReadWrite, vk::access::kComputeRead);
  // The blur, one axis per pass: 2 (2r + 1) reads a cell, against (2r + 1)² for the square kernel.
  const uint32_t n = std::min<uint32_t>(window.cells, LAGOON_CAUSTICS_CELLS);
  const gpu::CausticsBlurPush blur{.sigma_cells = window.blur_cells, .cells = glm::vec4(float(n), 0, 0, 0)};
  // An invocation per run of cells along a line (common/caustic_blur.glsl), a line per y, a slice per z.
  const std::array<uint32_t, 3> cells{(n + LAGOON_CAUSTICS_RUN - 1) / LAGOON_CAUSTICS_RUN, n,
                                      LAGOON_CAUSTICS_SLICES};
  vk::dispatch(frame.cmd, blur_rows_,
               {vk::bind(LAGOON_CAUSTICS_BIND_ACCUM, accum_), vk::bind(LAGOON_CAUSTICS_BIND_ROWS, rows_)},
               blur, vk::groups_for(blur_rows_, cells));
  // The resolve reads the rows, and clears the accumulation the rows have read for the next frame's splat.
  vk::buffer_barrier(frame.cmd, accum_.handle(), vk::access::kComputeRead, vk::access::kComputeWrite);
  vk::buffer_barrier(frame.cmd, rows_.handle(), vk::access::kComputeWrite, vk::access::kComputeRead);
  // The last frame's readers are done with the map before it is rewritten.
  vk::image_barrier(frame.cmd, map_.handle(), map_.all_subresources(), VK_IMAGE_LAYOUT_GENERAL,
                    VK_IMAGE_LAYOUT_GENERAL, vk::access::kGraphicsSampled, vk::access::kComputeWrite);
  vk::dispatch(frame.cmd, resolve_,
               {vk::bind(LAGOON_CAUSTICS_BIND_ACCUM, accum_), vk::bind(LAGOON_CAUSTICS_BIND_ROWS, rows_),
                vk::bind(LAGOON_CAUSTICS_BIND_MAP, vk::ImageRef{map_.view(), VK_IMAGE_LAYOUT_GENERAL})},
               blur, vk::groups_for(resolve_, cells));
  vk::image_barrier(frame.cmd, map_.handle(), map_.all_subresources(), VK_IMAGE_LAYOUT_GENERAL,
                    VK_IMAGE_LAYOUT_GENERAL, vk::access::kComputeWrite, vk::access::kGraphicsSampled);
  // The next frame's splat follows the clearing, and its rows this frame's resolve.
  vk::buffer_barrier(frame.cmd, accum_.handle(), vk::access::kComputeWrite, vk::access::kComputeReadWrite);
  vk::buffer_barrier(frame.cmd, rows_.handle(), vk::access::kComputeRead, vk::access::kComputeWrite);
}

std::vector<float> CausticsPass::read_map(vk::Context& ctx) const {
  const std::vector<std::byte> bytes =
      vk::readback_image(ctx, map_, VK_IMAGE_LAYOUT_GENERAL, vk::access::kGraphicsSampled);
  std::vector<float> out(bytes.size() / sizeof(float));
  std::memcpy(out.data(), bytes.data(), out.size() * sizeof(float));
  return out;
}

}  // namespace lagoon::render
