#include "world/object_pose.h"

#include <glm/gtc/matrix_transform.hpp>

#include "core/compass.h"

namespace lagoon::world {

glm::dquat object_orientation(const scene::Object& object) {
  const glm::dvec3 r = glm::radians(glm::dvec3(object.rotation_deg));
  return glm::angleAxis(compass::angle_about_up(r.x), glm::dvec3(0, 1, 0)) *
         glm::angleAxis(-r.y, glm::dvec3(1, 0, 0)) * glm::angleAxis(r.z, glm::dvec3(0, 0, 1));
}

glm::mat4 object_transform(glm::dvec3 origin, const glm::dquat& orientation, double scale) {
  const glm::dmat4 m = glm::translate(glm::dmat4(1.0), origin) * glm::mat4_cast(orientation) *
                       glm::scale(glm::dmat4(1.0), glm::dvec3(scale));
  return glm::mat4(m);
}

}  // namespace lagoon::world
