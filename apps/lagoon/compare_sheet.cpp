#include "compare_sheet.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "io/text_raster.h"

namespace lagoon::cli {
namespace {

constexpr io::Rgb8 kWhite{255, 255, 255}, kBand{24, 28, 36};
constexpr int kLabelHeight = 34;

// The render box-filtered down by a whole factor to at most `width` pixels across.
io::Image8 shrink(const io::Image8& in, uint32_t width) {
  const uint32_t f = std::max(1u, (in.width + width - 1) / width);
  io::Image8 out{.width = in.width / f, .height = in.height / f};
  out.rgba.resize(size_t{out.width} * out.height * 4);
  for (uint32_t y = 0; y < out.height; ++y)
    for (uint32_t x = 0; x < out.width; ++x)
      for (int c = 0; c < 4; ++c) {
        uint32_t sum = 0;
        for (uint32_t j = 0; j < f; ++j)
          for (uint32_t i = 0; i < f; ++i) sum += in.pixel(x * f + i, y * f + j)[c];
        out.pixel(x, y)[c] = uint8_t(sum / (f * f));
      }
  return out;
}

std::string figures(const ModelMeasure& m) {
  char text[160];
  std::snprintf(text, sizeof text, "Hs %.2f m   peak %.1f m, %.1f s   step %.2f ms", m.hs_m,
                m.peak_wavelength_m, m.peak_period_s, m.step_ms);
  return text;
}

// A perceptual ramp from dark blue through green to yellow (viridis' ends and middle), t in [0, 1].
io::Rgb8 viridis(double t) {
  static constexpr std::array<std::array<double, 3>, 5> stops{
      {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}}};
  t = std::clamp(t, 0.0, 1.0) * (stops.size() - 1);
  const size_t i = std::min(size_t(t), stops.size() - 2);
  const double f = t - double(i);
  io::Rgb8 out{};
  for (int c = 0; c < 3; ++c) out[c] = uint8_t(stops[i][c] + (stops[i + 1][c] - stops[i][c]) * f);
  return out;
}

}  // namespace

io::Image8 contact_sheet(const std::vector<ModelMeasure>& models, uint32_t columns, uint32_t tile_width) {
  std::vector<io::Image8> tiles;
  for (const ModelMeasure& m : models) tiles.push_back(shrink(m.render, tile_width));
  uint32_t w = 0, h = 0;
  for (const io::Image8& t : tiles) w = std::max(w, t.width), h = std::max(h, t.height);
  columns = std::min<uint32_t>(columns, uint32_t(tiles.size()));
  const uint32_t rows = (uint32_t(tiles.size()) + columns - 1) / columns, cell_h = h + kLabelHeight;
  io::Image8 sheet{.width = columns * w, .height = rows * cell_h};
  sheet.rgba.assign(size_t{sheet.width} * sheet.height * 4, 255);
  io::fill_rect(sheet, 0, 0, int(sheet.width), int(sheet.height), kBand);
  for (size_t i = 0; i < tiles.size(); ++i) {
    const int x0 = int(i % columns * w), y0 = int(i / columns * cell_h);
    io::draw_text(sheet, x0 + 6, y0 + 4, models[i].model, kWhite, 2);
    io::draw_text(sheet, x0 + 6, y0 + 22, figures(models[i]), {200, 210, 220}, 1);
    for (uint32_t y = 0; y < tiles[i].height; ++y)
      for (uint32_t x = 0; x < tiles[i].width; ++x)
        std::copy_n(tiles[i].pixel(x, y), 4, sheet.pixel(uint32_t(x0) + x, uint32_t(y0 + kLabelHeight) + y));
  }
  return sheet;
}

io::Image8 spectrum_plot(const ModelMeasure& model) {
  const ocean::ModeEnergy& e = model.spectrum;
  const uint32_t scale = std::max(1u, 512 / e.n), side = e.n * scale, top = 40, bottom = 24;
  io::Image8 plot{.width = side, .height = side + top + bottom};
  plot.rgba.assign(size_t{plot.width} * plot.height * 4, 255);
  io::fill_rect(plot, 0, 0, int(plot.width), int(plot.height), kBand);
  const double largest = *std::max_element(e.energy.begin(), e.energy.end());
  const double floor_log = std::log10(std::max(largest, 1e-300)) - 6;
  for (uint32_t row = 0; row < e.n; ++row)
    for (uint32_t col = 0; col < e.n; ++col) {
      // Column: kx from -n/2 (left) to n/2 - 1; row: kz from n/2 - 1 (top) down to -n/2.
      const uint32_t ix = (col + e.n / 2) % e.n, iz = (e.n - 1 - row + e.n / 2) % e.n;
      const double v = e.energy[size_t{iz} * e.n + ix];
      const io::Rgb8 c = v > 0 ? viridis((std::log10(v) - floor_log) / 6) : viridis(0);
      io::fill_rect(plot, int(col * scale), int(top + row * scale), int(scale), int(scale), c);
    }
  io::draw_text(plot, 6, 4, model.model + "  log10 E(kx, kz)", kWhite, 2);
  char title[160];
  std::snprintf(title, sizeof title, "energy per mode of the first cascade (%.0f m patch, %u^2 modes)",
                e.patch_m, e.n);
  io::draw_text(plot, 6, 24, title, {200, 210, 220}, 1);
  char axes[160];
  const double k_nyquist = 3.14159265358979 * e.n / e.patch_m;
  std::snprintf(axes, sizeof axes,
                "kx right, kz up, k = 0 in the middle; edges at +-%.3g rad/m; 6 decades shown", k_nyquist);
  io::draw_text(plot, 6, int(top + side + 6), axes, {200, 210, 220}, 1);
  return plot;
}

}  // namespace lagoon::cli
