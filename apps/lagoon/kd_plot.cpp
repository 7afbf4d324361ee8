#include "kd_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "io/text_raster.h"
#include "optics/csv_table.h"
#include "optics/kd.h"
#include "optics/lut.h"

namespace lagoon::cli {
namespace {

constexpr int kPanelW = 300, kPanelH = 200, kKdColumns = 5, kMargin = 34, kKdTitleHeight = 40;
constexpr io::Rgb8 kJerlov{255, 255, 255}, kSeed{240, 150, 60}, kIsotropic{80, 200, 230};
constexpr double kLogMin = -2.0, kLogMax = 1.0;  // K_d from 0.01 to 10 per metre

struct KdPanel {
  int x0, y0;
  int px(double nm) const { return x0 + kMargin + int((nm - 400) / 300.0 * (kPanelW - kMargin - 8)); }
  int py(double kd) const {
    const double t = (std::log10(std::max(kd, 1e-3)) - kLogMin) / (kLogMax - kLogMin);
    return y0 + kPanelH - 18 - int(std::clamp(t, 0.0, 1.0) * (kPanelH - 36));
  }
};

void axes(io::Image8& img, const KdPanel& p, const std::string& type) {
  io::draw_line(img, p.px(400), p.py(1e-2), p.px(700), p.py(1e-2), io::chart::kAxis);
  io::draw_line(img, p.px(400), p.py(1e-2), p.px(400), p.py(10), io::chart::kAxis);
  for (double kd : {0.01, 0.1, 1.0, 10.0}) {
    char label[16];
    std::snprintf(label, sizeof label, "%g", kd);
    io::draw_text(img, p.x0 + 2, p.py(kd) - 3, label, io::chart::kAxis);
  }
  for (int nm : {400, 500, 600, 700})
    io::draw_text(img, p.px(nm) - 8, p.y0 + kPanelH - 12, std::to_string(nm), io::chart::kAxis);
  io::draw_text(img, p.px(560), p.y0 + 6, "jerlov-" + type, io::chart::kText, 2);
}

}  // namespace

Result<io::Image8> kd_plot() {
  auto table = optics::CsvTable::embedded("jerlov1976_kd_table27.csv");
  if (!table) return table.error();
  const char* types[] = {"I", "IA", "IB", "II", "III", "1C", "3C", "5C", "7C", "9C"};
  const int rows = (int(std::size(types)) + kKdColumns - 1) / kKdColumns;
  io::Image8 img{.width = uint32_t(kKdColumns * kPanelW),
                 .height = uint32_t(kKdTitleHeight + rows * kPanelH)};
  img.rgba.assign(size_t{img.width} * img.height * 4, 255);
  io::fill_rect(img, 0, 0, int(img.width), int(img.height), io::chart::kBackground);
  int x = io::draw_text(img, 8, 6, "K_d (1/m) against wavelength (nm): ", io::chart::kText, 2) + 8;
  x += io::draw_text(img, x, 6, "Jerlov 1976 (dots)  ", kJerlov, 2);
  x += io::draw_text(img, x, 6, "model D = 1 (seed)  ", kSeed, 2);
  io::draw_text(img, x, 6, "model D = 2", kIsotropic, 2);
  io::draw_text(img, 8, 24, "deep water, K_d = -d ln(Ed)/dz between 5 and 10 m, sun 60 deg above the horizon",
                io::chart::kAxis);
  const auto nm = table->numbers("wavelength_nm");
  if (!nm) return nm.error();
  for (size_t t = 0; t < std::size(types); ++t) {
    const KdPanel p{int(t % kKdColumns) * kPanelW, kKdTitleHeight + int(t / kKdColumns) * kPanelH};
    axes(img, p, types[t]);
    optics::WaterParams params;
    params.type = std::string("jerlov-") + types[t];
    auto in = optics::lut_inputs(params, 60.0);
    if (!in) return in.error();
    for (double d : {1.0, 2.0}) {
      int last_x = -1, last_y = -1;
      for (int i = 0; i < optics::kSamples; ++i) {
        const double lambda = optics::kLambdaMinNm + optics::kLambdaStepNm * i;
        if (lambda < 400 || lambda > 700) continue;
        const int px = p.px(lambda), py = p.py(optics::model_kd(*in, i, d));
        if (last_x >= 0) io::draw_line(img, last_x, last_y, px, py, d == 1.0 ? kSeed : kIsotropic);
        last_x = px, last_y = py;
      }
    }
    const auto measured = table->numbers(types[t]);
    if (!measured) return measured.error();
    for (size_t r = 0; r < nm->size(); ++r)
      if ((*nm)[r] >= 400 && (*nm)[r] <= 700)
        io::fill_rect(img, p.px((*nm)[r]) - 2, p.py((*measured)[r]) - 2, 5, 5, kJerlov);
  }
  return img;
}

}  // namespace lagoon::cli
