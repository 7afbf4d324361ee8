// The JSON written beside each frame of a dataset (docs/datasets.md): OpenCV pinhole intrinsics K, the
// camera's pose in the world (and in ENU and NED), the time, the sun, the water type and the seeds: what it
// takes to reproduce the frame and to use it with robotics tools. Nothing in it depends on the device or on
// which shard drew it, so a sharded set is byte-identical to one drawn in one process. `lagoon render` writes
// it for every frame of a sequence, and the Python module returns it with each frame.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.h"

namespace lagoon::dataset {

// The world frame's axes in east-north-up: Lagoon's world is right-handed with y up; x is east and -z north.
// Columns: where world x, y, z point in ENU.
inline constexpr float kEnuFromWorld[3][3] = {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}};  // [enu row][world column]

struct FrameFiles {
  std::string image;              // the PNG's file name
  std::vector<std::string> aovs;  // "depth" -> file name, in the order written
  std::vector<std::string> aov_files;
};

nlohmann::ordered_json frame_metadata(const scene::Scene& scene, long long frame, const FrameFiles& files);

}  // namespace lagoon::dataset
