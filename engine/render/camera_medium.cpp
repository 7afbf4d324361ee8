#include "render/camera_medium.h"

namespace lagoon::render {

bool CameraMedium::under_water(const glm::vec3& camera, double time_s) {
  last_queried_ = false;
  if (camera.y > reach_m_) return false;
  if (camera.y < -reach_m_) return true;
  if (!query_) query_ = std::make_unique<ocean::WaveQuery>(params_, spectra_);
  last_queried_ = true;
  return camera.y < query_->sample(time_s, camera.x, camera.z).height;
}

}  // namespace lagoon::render
