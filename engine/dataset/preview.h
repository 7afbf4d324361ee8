// lagoon dataset preview FRAME.json: one frame of a dataset and its ground truth side by side in a labelled
// PNG, drawn by Lagoon (docs/datasets.md): the image, then each AOV the frame's JSON lists, in false colour
// (depth on a log grey scale with the sky dark blue, normals as RGB, the water mask and object ids in a
// palette, clean and backscatter tone-mapped, transmission as RGB; NaN dark purple).
#pragma once
#include <filesystem>

#include "core/result.h"
#include "io/png.h"

namespace lagoon::dataset {

// Fails naming the file when the JSON is not a frame's metadata or an image or AOV it lists is missing or of
// another size.
Result<io::Image8> preview(const std::filesystem::path& frame_json);

}  // namespace lagoon::dataset
