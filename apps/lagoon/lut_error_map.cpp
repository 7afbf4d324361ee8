#include "lut_error_map.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <vector>

#include "io/atomic_file.h"
#include "io/staged_output.h"
#include "io/text_raster.h"
#include "optics/bottom_spectra.h"
#include "optics/colour.h"
#include "optics/composite_error.h"

namespace lagoon::cli {
namespace {

constexpr int kCell = 2;  // pixels per LUT node
constexpr int kGap = 8, kLabelW = 190, kTitleHeight = 44, kColumnHeader = 16, kLegend = 46;
// The summary covers the nodes where the bottom shows (a >= 2 %): elsewhere all composites are the water.
constexpr double kMinBottomShare = 0.02;

struct Bottom {
  std::string name;
  optics::Spectrum reflectance;
};

std::vector<Bottom> bottoms() {
  std::vector<Bottom> out;
  for (const optics::BottomSpectrum& b : optics::bottom_spectra()) out.push_back({b.name, b.reflectance});
  optics::Spectrum grey{};
  grey.fill(0.3);
  out.push_back({"grey 0.3", grey});
  return out;
}

// ΔE00 to colour: 0 near black, 1 blue, 2 green, 5 yellow, 10 orange, 20 and above red.
io::Rgb8 delta_e_colour(double de) {
  struct Stop {
    double at;
    double r, g, b;
  };
  constexpr Stop stops[] = {{0, 16, 18, 30},   {1, 40, 90, 210},   {2, 40, 180, 120},
                            {5, 235, 215, 50}, {10, 245, 125, 30}, {20, 235, 40, 40}};
  if (de >= stops[5].at) return {235, 40, 40};
  for (int k = 1; k < 6; ++k)
    if (de <= stops[k].at) {
      const double t = (de - stops[k - 1].at) / (stops[k].at - stops[k - 1].at);
      auto mix = [&](double a, double b) { return uint8_t(std::lround(a + t * (b - a))); };
      return {mix(stops[k - 1].r, stops[k].r), mix(stops[k - 1].g, stops[k].g),
              mix(stops[k - 1].b, stops[k].b)};
    }
  return {16, 18, 30};
}

io::Rgb8 display_colour(glm::dvec3 linear) {
  const glm::dvec3 e = optics::encode_srgb(glm::clamp(linear, 0.0, 1.0));
  return {uint8_t(std::lround(e.x * 255)), uint8_t(std::lround(e.y * 255)), uint8_t(std::lround(e.z * 255))};
}

// One panel: node (i, j) at column i (r), row j (h), both on the LUT's square-root axes.
template <typename Colour>
void panel(io::Image8& img, int x0, int y0, uint32_t n, Colour colour_of) {
  for (uint32_t i = 0; i < n; ++i)
    for (uint32_t j = 0; j < n; ++j)
      io::fill_rect(img, x0 + int(i) * kCell, y0 + int(j) * kCell, kCell, kCell,
                    colour_of(size_t{i} * n + j));
}

void legend(io::Image8& img, int x0, int y0) {
  io::draw_text(img, x0, y0, "CIEDE2000 against eq. 20:", io::chart::kText);
  const int bar_x = x0 + 170, bar_w = 400;
  for (int x = 0; x < bar_w; ++x)
    io::fill_rect(img, bar_x + x, y0, 1, 12, delta_e_colour(20.0 * x / (bar_w - 1)));
  for (double tick : {0.0, 1.0, 2.0, 5.0, 10.0, 20.0}) {
    const int tx = bar_x + int(tick / 20.0 * (bar_w - 1));
    io::fill_rect(img, tx, y0 + 12, 1, 4, io::chart::kText);
    io::draw_text(img, tx - 3, y0 + 18, std::to_string(int(tick)), io::chart::kText);
  }
  io::draw_text(img, x0, y0 + 30,
                "each panel: r (distance under water) to the right, h (depth) down, both from 0 on sqrt axes "
                "(as T0.png); 1 = just noticeable",
                io::chart::kDim);
}

struct Column {
  std::string title;
  optics::Composite composite;
  bool clipped_tables;
};

Result<io::Image8> sheet(const optics::LutInputs& in, optics::PhiMode mode, const std::vector<Bottom>& list,
                         nlohmann::json& rows) {
  std::vector<Column> columns = {{"eq. 21", optics::Composite::Eq21, true},
                                 {"eq. 22 (the LUTs)", optics::Composite::Eq22, true},
                                 {"eq. 24", optics::Composite::Eq24, true}};
  if (mode == optics::PhiMode::Linear)
    columns.insert(columns.begin() + 2, {"eq. 22, signed tables", optics::Composite::Eq22, false});
  const uint32_t n = std::max(2u, in.params.lut_size);
  const int side = int(n) * kCell;
  io::Image8 img{
      .width = uint32_t(kLabelW + (int(columns.size()) + 1) * (side + kGap)),
      .height = uint32_t(kTitleHeight + kColumnHeader + int(list.size()) * (side + kGap) + kLegend)};
  img.rgba.assign(size_t{img.width} * img.height * 4, 255);
  io::fill_rect(img, 0, 0, int(img.width), int(img.height), io::chart::kBackground);
  io::draw_text(img, 8, 6, "eqs. 21, 22, 24 against eq. 20, " + in.params.type, io::chart::kText, 2);
  char sub[256];
  std::snprintf(sub, sizeof sub, "Phi %s; sun %.0f deg, r 0..%.0f m, h 0..%.0f m, gamma %.2f",
                mode == optics::PhiMode::Linear ? "linear (Lagoon: one tone map, after compositing)"
                                                : "tone-mapped per table (the seed's)",
                in.sky.sun_elevation_deg, in.params.lut_r_max_m, in.params.lut_h_max_m, in.params.lut_gamma);
  io::draw_text(img, 8, 26, sub, io::chart::kDim);
  const int y_columns = kTitleHeight;
  io::draw_text(img, kLabelW, y_columns, "eq. 20 (exact)", io::chart::kText);
  for (size_t c = 0; c < columns.size(); ++c)
    io::draw_text(img, kLabelW + int(c + 1) * (side + kGap), y_columns, columns[c].title, io::chart::kText);
  for (size_t b = 0; b < list.size(); ++b) {
    const int y0 = kTitleHeight + kColumnHeader + int(b) * (side + kGap);
    io::draw_text(img, 8, y0 + side / 2 - 4, list[b].name, io::chart::kText, 2);
    auto clipped = optics::composite_errors(in, list[b].reflectance, mode, true);
    if (!clipped) return clipped.error();
    auto signed_tables = optics::composite_errors(in, list[b].reflectance, mode, false);
    if (!signed_tables) return signed_tables.error();
    panel(img, kLabelW, y0, n, [&](size_t k) { return display_colour(clipped->exact[k]); });
    for (size_t c = 0; c < columns.size(); ++c) {
      const optics::CompositeErrors& e = columns[c].clipped_tables ? *clipped : *signed_tables;
      const std::vector<double>& de = e.delta_e[int(columns[c].composite)];
      panel(img, kLabelW + int(c + 1) * (side + kGap), y0, n,
            [&](size_t k) { return delta_e_colour(de[k]); });
      const optics::ErrorSummary s = optics::summarise(e, columns[c].composite, kMinBottomShare);
      rows.push_back({{"phi", optics::phi_mode_name(mode)},
                      {"bottom", list[b].name},
                      {"equation", optics::composite_name(columns[c].composite)},
                      {"tables", columns[c].clipped_tables ? "clipped" : "signed"},
                      {"mean", s.mean},
                      {"p95", s.p95},
                      {"max", s.max},
                      {"visible_share", s.visible_share}});
    }
    std::printf("  %s, Phi %s: done\n", list[b].name.c_str(), optics::phi_mode_name(mode));
    std::fflush(stdout);
  }
  legend(img, 8, int(img.height) - kLegend + 4);
  return img;
}

std::string summary_csv(const nlohmann::json& rows) {
  std::string csv = "phi,bottom,equation,tables,mean_de2000,p95_de2000,max_de2000,share_above_2\n";
  char line[256];
  for (const auto& r : rows) {
    std::snprintf(line, sizeof line, "%s,%s,%s,%s,%.3f,%.3f,%.3f,%.3f\n", r["phi"].get<std::string>().c_str(),
                  r["bottom"].get<std::string>().c_str(), r["equation"].get<std::string>().c_str(),
                  r["tables"].get<std::string>().c_str(), r["mean"].get<double>(), r["p95"].get<double>(),
                  r["max"].get<double>(), r["visible_share"].get<double>());
    csv += line;
  }
  return csv;
}

std::string summary_markdown(const nlohmann::json& rows, const optics::LutInputs& in) {
  std::string md = "CIEDE2000 of each composite against eq. 20 over the nodes of the " +
                   std::to_string(in.params.lut_size) + "x" + std::to_string(in.params.lut_size) +
                   " LUT grid where the bottom shows (a >= 2 %), " + in.params.type + ":\n\n";
  md +=
      "| Phi | bottom | equation | tables | mean | p95 | max | share > 2 "
      "|\n|---|---|---|---|---|---|---|---|\n";
  char line[256];
  for (const auto& r : rows) {
    std::snprintf(line, sizeof line, "| %s | %s | %s | %s | %.2f | %.2f | %.2f | %.0f %% |\n",
                  r["phi"].get<std::string>().c_str(), r["bottom"].get<std::string>().c_str(),
                  r["equation"].get<std::string>().c_str(), r["tables"].get<std::string>().c_str(),
                  r["mean"].get<double>(), r["p95"].get<double>(), r["max"].get<double>(),
                  100 * r["visible_share"].get<double>());
    md += line;
  }
  return md;
}

}  // namespace

Result<void> write_error_maps(const optics::LutInputs& in, const std::string& out) {
  auto staged = io::StagedOutput::create(out);
  if (!staged) return staged.error();
  const std::vector<Bottom> list = bottoms();
  nlohmann::json rows = nlohmann::json::array();
  for (optics::PhiMode mode : {optics::PhiMode::Linear, optics::PhiMode::Seed}) {
    auto img = sheet(in, mode, list, rows);
    if (!img) return img.error();
    const std::string name = std::string("error_maps_") + optics::phi_mode_name(mode) + ".png";
    if (auto w = io::write_png(staged->file(name), *img); !w) return w.error();
  }
  if (auto w = io::write_text_atomic(staged->file("error_summary.csv"), summary_csv(rows)); !w)
    return w.error();
  if (auto w = io::write_text_atomic(staged->file("error_summary.md"), summary_markdown(rows, in)); !w)
    return w.error();
  nlohmann::json bottoms_json = nlohmann::json::array();
  for (const optics::BottomSpectrum& b : optics::bottom_spectra())
    bottoms_json.push_back({{"name", b.name}, {"source", b.description}});
  bottoms_json.push_back(
      {{"name", "grey 0.3"}, {"source", "a flat reflectance of 0.3 (eq. 22 is exact for it)"}});
  const nlohmann::json meta = {
      {"format_version", 1},
      {"generator", "lagoon lut --error-map"},
      {"water_type", in.params.type},
      {"sun_elevation_deg", in.sky.sun_elevation_deg},
      {"lut_size", in.params.lut_size},
      {"r_max_m", in.params.lut_r_max_m},
      {"h_max_m", in.params.lut_h_max_m},
      {"gamma", in.params.lut_gamma},
      {"bottoms", bottoms_json},
      {"summary", rows},
      {"about",
       "delta E: CIEDE2000 between eq. 20 and each composite as displayed (tone-mapped, clipped to [0, 1]) "
       "at every LUT node (the PNG maps); the summary covers the nodes where the bottom shows (eq. 23's a >= "
       "0.02); tables 'clipped' are clipped at 0 as the LUTs are, 'signed' keep their negative channels "
       "(docs/optics.md)"}};
  if (auto w = io::write_text_atomic(staged->file("error.json"), meta.dump(2) + "\n"); !w) return w.error();
  return staged->commit();
}

}  // namespace lagoon::cli
