// camera.gltf: a scene's camera taken from a camera node of a glTF file (issue 17, item 3). glTF cameras
// look down their local −Z with +Y up; Lagoon's is a position, a point looked at, an up direction and a
// perspective lens, so the node's world transform and the camera's yfov, znear and zfar map onto those.
#pragma once
#include <string>

#include "core/result.h"
#include "scene/scene.h"

namespace lagoon::scene {

// Sets scene.camera from camera.gltf when its file is given (already resolved against the scene's folder);
// otherwise does nothing. Errors name `scene_name`, the field and the fix: a file that does not load, a name
// the file does not have (the names it has are listed), an orthographic camera.
Result<void> apply_gltf_camera(Scene& scene, const std::string& scene_name);

}  // namespace lagoon::scene
