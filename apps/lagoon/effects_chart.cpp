#include "effects_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/text_raster.h"

namespace lagoon::cli {
namespace {

constexpr int kWidth = 900, kRow = 34, kTop = 56, kLeft = 130, kRight = 70, kBottom = 40;
constexpr io::Rgb8 kBar{70, 150, 220}, kAll{240, 150, 60}, kWhisker{235, 235, 235};

// A round axis end above `v`: 1, 2 or 5 times a power of ten.
double nice_ceiling(double v) {
  const double p = std::pow(10.0, std::floor(std::log10(v)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= v) return m * p;
  return 10 * p;
}

std::string axis_label(double v) {
  char text[32];
  std::snprintf(text, sizeof(text), v < 10 ? "%.1f" : "%.0f", v);
  return text;
}

}  // namespace

Result<io::Image8> effects_chart(const std::vector<EffectBar>& bars, const std::string& device) {
  if (bars.empty()) return Error{"no tests to draw"};
  for (const EffectBar& b : bars)
    if (!(b.min_fps > 0 && b.avg_fps > 0 && b.max_fps > 0) || !std::isfinite(b.max_fps))
      return Error{"test " + b.name + " has no positive frame rate to draw"};
  const int height = kTop + int(bars.size()) * kRow + kBottom;
  io::Image8 img{.width = kWidth, .height = uint32_t(height)};
  img.rgba.assign(size_t{img.width} * img.height * 4, 255);
  io::fill_rect(img, 0, 0, kWidth, height, io::chart::kBackground);
  io::draw_text(img, 10, 8, "Frames per second along the evaluation flight", io::chart::kText, 2);
  io::draw_text(img, 10, 32, device + "   bar: mean   whisker: min to max", io::chart::kAxis);

  double top = 0;
  for (const EffectBar& b : bars) top = std::max(top, b.max_fps);
  top = nice_ceiling(top);
  const int plot_w = kWidth - kLeft - kRight;
  auto x_of = [&](double fps) { return kLeft + int(std::round(fps / top * plot_w)); };
  for (int i = 0; i <= 5; ++i) {
    const double v = top * i / 5;
    io::fill_rect(img, x_of(v), kTop - 4, 1, int(bars.size()) * kRow + 8, io::chart::kAxis);
    io::draw_text(img, x_of(v) - 8, height - kBottom + 10, axis_label(v), io::chart::kAxis);
  }
  io::draw_text(img, kLeft + plot_w / 2 - 20, height - 16, "FPS", io::chart::kText);
  for (size_t i = 0; i < bars.size(); ++i) {
    const EffectBar& b = bars[i];
    const int y = kTop + int(i) * kRow;
    io::draw_text(img, 10, y + 9, b.name, io::chart::kText, 2);
    io::fill_rect(img, kLeft, y + 6, x_of(b.avg_fps) - kLeft, kRow - 12, b.name == "all" ? kAll : kBar);
    io::fill_rect(img, x_of(b.min_fps), y + kRow / 2 - 1, std::max(1, x_of(b.max_fps) - x_of(b.min_fps)), 2,
                  kWhisker);
    for (double end : {b.min_fps, b.max_fps}) io::fill_rect(img, x_of(end), y + 10, 2, kRow - 20, kWhisker);
    io::draw_text(img, x_of(b.max_fps) + 6, y + 12, axis_label(b.avg_fps), io::chart::kText);
  }
  return img;
}

}  // namespace lagoon::cli
