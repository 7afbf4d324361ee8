#include "dataset/preview.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/bounded_file.h"
#include "dataset/ground_truth.h"
#include "io/json_limits.h"
#include "io/npy.h"
#include "io/text_raster.h"

namespace lagoon::dataset {
namespace {

namespace fs = std::filesystem;
using io::Rgb8;

constexpr int kPanelColumns = 4, kLabel = 18;
constexpr Rgb8 kSky{10, 20, 70}, kNan{60, 0, 60};

struct PreviewPanel {
  std::string label;
  std::vector<Rgb8> pixels;  // W x H
};

uint8_t byte(double v) {
  return uint8_t(std::clamp(std::round(255.0 * v), 0.0, 255.0));
}

// Linear light for a look: x / (1 + x) per channel, then gamma 2.2.
Rgb8 tone(const float* c) {
  Rgb8 out;
  for (int i = 0; i < 3; ++i) out[i] = byte(std::pow(std::max(double(c[i]), 0.0) / (1.0 + c[i]), 1 / 2.2));
  return out;
}

Rgb8 palette(int k) {
  if (k == 0) return {0, 0, 0};
  if (k == -1) return {200, 180, 90};  // the floor
  const double h = std::fmod(0.618034 * k, 1.0) * 6.0;
  const double f = h - std::floor(h);
  const double rgb[6][3] = {{1, f, 0}, {1 - f, 1, 0}, {0, 1, f}, {0, 1 - f, 1}, {f, 0, 1}, {1, 0, 1 - f}};
  const double* c = rgb[int(h) % 6];
  return {byte(0.25 + 0.75 * c[0]), byte(0.25 + 0.75 * c[1]), byte(0.25 + 0.75 * c[2])};
}

std::vector<Rgb8> colour(const std::string& kind, const io::NpyArray& a, size_t pixels) {
  std::vector<Rgb8> out(pixels);
  const float* v = a.data.data();
  if (kind == "depth") {
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    for (size_t i = 0; i < pixels; ++i)
      if (std::isfinite(v[i]) && v[i] > 0) lo = std::min(lo, double(v[i])), hi = std::max(hi, double(v[i]));
    const double span = std::max(std::log(hi / lo), 1e-6);
    for (size_t i = 0; i < pixels; ++i) {
      if (!std::isfinite(v[i]) || v[i] <= 0) {
        out[i] = std::isnan(v[i]) ? kNan : kSky;
        continue;
      }
      const uint8_t g = byte(1.0 - 0.85 * std::log(v[i] / lo) / span);
      out[i] = {g, g, g};
    }
  } else if (kind == "normal") {
    for (size_t i = 0; i < pixels; ++i)
      out[i] = {byte(0.5 + 0.5 * v[3 * i]), byte(0.5 + 0.5 * v[3 * i + 1]), byte(0.5 + 0.5 * v[3 * i + 2])};
  } else if (kind == "water_mask") {
    const Rgb8 mask[3] = {{40, 40, 40}, {30, 120, 255}, {20, 200, 120}};
    for (size_t i = 0; i < pixels; ++i) out[i] = mask[std::clamp(int(v[i]), 0, 2)];
  } else if (kind == "object_id") {
    for (size_t i = 0; i < pixels; ++i) out[i] = palette(int(std::lround(v[i])));
  } else {  // clean, transmission, backscatter: three channels of linear light or shares
    for (size_t i = 0; i < pixels; ++i) {
      const float* c = v + 3 * i;
      if (std::isnan(c[0]))
        out[i] = kNan;
      else if (kind == "transmission")
        out[i] = {byte(std::pow(c[0], 1 / 2.2)), byte(std::pow(c[1], 1 / 2.2)),
                  byte(std::pow(c[2], 1 / 2.2))};
      else
        out[i] = tone(c);
    }
  }
  return out;
}

Result<nlohmann::ordered_json> read_metadata(const fs::path& path) {
  Result<std::string> text = read_bounded_file(path, std::uintmax_t{1} << 20);
  if (!text)
    return Error{path.string() + ": " + text.error().message +
                 "; name a frame's .json written by lagoon render (at most 1 MiB)"};
  const std::string& s = *text;
  if (io::json_limit_exceeded(s, {}))
    return Error{path.string() + ": is not a frame's metadata (too large or too deeply nested)"};
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(s, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("image") || !j["image"].is_string() ||
      !j.contains("width") || !j["width"].is_number_unsigned() || !j.contains("height") ||
      !j["height"].is_number_unsigned())
    return Error{path.string() +
                 ": is not a frame's metadata (it needs \"image\", \"width\" and \"height\", as "
                 "lagoon render writes beside each frame)"};
  return j;
}

// Only plain names beside the JSON, as lagoon render writes them.
bool plain_name(const std::string& name) {
  return !name.empty() && name.find('/') == std::string::npos && name != "." && name != "..";
}

}  // namespace

Result<io::Image8> preview(const fs::path& frame_json) {
  Result<nlohmann::ordered_json> meta = read_metadata(frame_json);
  if (!meta) return meta.error();
  const fs::path folder = frame_json.parent_path();
  const std::string image_name = (*meta)["image"];
  if (!plain_name(image_name))
    return Error{frame_json.string() + ": \"image\" must be a file name beside it"};
  Result<io::Image8> image = io::read_png(folder / image_name);
  if (!image) return image.error();
  const uint32_t w = image->width, h = image->height;
  if (w != (*meta)["width"] || h != (*meta)["height"])
    return Error{(folder / image_name).string() + " is " + std::to_string(w) + "x" + std::to_string(h) +
                 ", the metadata says otherwise"};
  const size_t pixels = size_t{w} * h;
  std::vector<PreviewPanel> panels(1, PreviewPanel{"image", std::vector<Rgb8>(pixels)});
  for (size_t i = 0; i < pixels; ++i)
    panels[0].pixels[i] = {image->rgba[4 * i], image->rgba[4 * i + 1], image->rgba[4 * i + 2]};
  if (meta->contains("aov") && (*meta)["aov"].is_object())
    for (const auto& [kind, file] : (*meta)["aov"].items()) {
      if (!file.is_string() || !plain_name(file.get<std::string>()))
        return Error{frame_json.string() + ": aov." + kind + " must be a file name beside it"};
      const fs::path path = folder / file.get<std::string>();
      const AovKind* aov = find_aov(kind);
      if (!aov)
        return Error{frame_json.string() + ": aov." + kind + " is not a ground truth lagoon render writes"};
      Result<io::NpyArray> a = io::read_npy(path);
      if (!a) return a.error();
      const std::vector<size_t> shape =
          aov->channels == 3 ? std::vector<size_t>{h, w, 3} : std::vector<size_t>{h, w};
      if (a->shape != shape)
        return Error{path.string() + ": " + kind + " is not " + std::to_string(h) + " x " +
                     std::to_string(w) + (aov->channels == 3 ? " x 3" : "") + " like its frame"};
      panels.push_back({kind, colour(kind, *a, pixels)});
    }
  const int columns = std::min<int>(kPanelColumns, int(panels.size())),
            rows = (int(panels.size()) + columns - 1) / columns;
  io::Image8 sheet{.width = uint32_t(columns * int(w)), .height = uint32_t(rows * (int(h) + kLabel))};
  sheet.rgba.assign(size_t{sheet.width} * sheet.height * 4, 255);
  io::fill_rect(sheet, 0, 0, int(sheet.width), int(sheet.height), io::chart::kBackground);
  for (size_t p = 0; p < panels.size(); ++p) {
    const int x0 = int(p % columns) * int(w), y0 = int(p / columns) * (int(h) + kLabel);
    io::draw_text(sheet, x0 + 4, y0 + 4, panels[p].label, io::chart::kText);
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x) {
        const Rgb8 c = panels[p].pixels[size_t{y} * w + x];
        uint8_t* out = &sheet.rgba[(size_t(y0 + kLabel + int(y)) * sheet.width + size_t(x0) + x) * 4];
        out[0] = c[0], out[1] = c[1], out[2] = c[2], out[3] = 255;
      }
  }
  return sheet;
}

}  // namespace lagoon::dataset
