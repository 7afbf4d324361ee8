// The pictures of `lagoon compare`: the contact sheet (every model's render, labelled with its name and
// figures) and one model's directional spectrum plot (log energy over the first cascade's (kx, kz) plane).
#pragma once
#include <vector>

#include "io/png.h"
#include "model_comparison.h"

namespace lagoon::cli {

// Tiles of at most `tile_width` pixels, `columns` across, each with its label band.
io::Image8 contact_sheet(const std::vector<ModelMeasure>& models, uint32_t columns = 3,
                         uint32_t tile_width = 480);

// log10 of each mode's energy, the 6 decades below the largest in a colour ramp; +kx right, +kz up, k = 0 in
// the middle; titled with the model and the patch.
io::Image8 spectrum_plot(const ModelMeasure& model);

}  // namespace lagoon::cli
