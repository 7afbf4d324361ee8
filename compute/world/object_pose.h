// Where a scene object (objects[]) is drawn: T(position) · Ry(π − yaw) · Rx(−pitch) · Rz(roll) · S(scale)
// (docs/scene-format.md, Objects). One definition for the objects placed by the scene and for the floating
// bodies that start from it.
#pragma once
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>

#include "scene/scene.h"

namespace lagoon::world {

// The rotation part, model to world.
glm::dquat object_orientation(const scene::Object& object);
// The whole placement of the model, for a model origin at `origin` turned by `orientation`.
glm::mat4 object_transform(glm::dvec3 origin, const glm::dquat& orientation, double scale);
inline glm::mat4 object_transform(const scene::Object& object) {
  return object_transform(glm::dvec3(object.position), object_orientation(object), object.scale);
}

}  // namespace lagoon::world
