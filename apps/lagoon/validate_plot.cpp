#include "validate_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>

#include "io/text_raster.h"

namespace lagoon::cli {
namespace {

constexpr int kWidth = 640, kHeight = 400, kLeft = 70, kRight = 20, kTop = 50, kBottom = 50;
constexpr io::Rgb8 kReference{240, 200, 90}, kBand{60, 66, 80}, kHolds{90, 210, 120}, kFails{235, 80, 70};

// One axis: the data range, linear or logarithmic, mapped to pixels.
struct Axis {
  double lo = 0, hi = 1;
  bool log = false;
  int from = 0, to = 1;  // pixels of lo and hi
  double value(double v) const { return log ? std::log10(std::max(v, 1e-300)) : v; }
  int pixel(double v) const {
    const double t = (value(v) - value(lo)) / std::max(value(hi) - value(lo), 1e-300);
    return from + int(std::lround(std::clamp(t, -0.05, 1.05) * (to - from)));
  }
};

Axis fit(const std::vector<double>& values, bool log, int from, int to) {
  Axis a{.log = log, .from = from, .to = to};
  a.lo = 1e300, a.hi = -1e300;
  for (double v : values)
    if (std::isfinite(v) && (!log || v > 0)) a.lo = std::min(a.lo, v), a.hi = std::max(a.hi, v);
  if (a.lo > a.hi) a.lo = log ? 0.1 : 0.0, a.hi = 1.0;
  if (log) {
    a.lo /= 1.15, a.hi *= 1.15;
  } else {
    const double pad = 0.06 * std::max(a.hi - a.lo, std::abs(a.hi) * 1e-3 + 1e-12);
    a.lo -= pad, a.hi += pad;
  }
  return a;
}

// The chart font is plain ASCII: the symbols the laws' texts use, spelled out.
std::string ascii(std::string text) {
  const std::pair<const char*, const char*> symbols[] = {{"±", "+/-"},  {"°", " deg"}, {"≤", "<="},
                                                         {"√", "sqrt"}, {"²", "^2"},   {"³", "^3"},
                                                         {"ω", "w"},    {"χ", "chi"}};
  for (const auto& [from, to] : symbols)
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + std::strlen(to)))
      text.replace(at, std::strlen(from), to);
  return text;
}

std::string label(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

void ticks(io::Image8& img, const Axis& x, const Axis& y) {
  for (int i = 0; i <= 4; ++i) {
    const auto at = [&](const Axis& a) {
      const double t = i / 4.0;
      return a.log ? std::pow(10.0, a.value(a.lo) + t * (a.value(a.hi) - a.value(a.lo)))
                   : a.lo + t * (a.hi - a.lo);
    };
    const double xv = at(x), yv = at(y);
    io::draw_text(img, x.pixel(xv) - 10, kHeight - kBottom + 8, label(xv), io::chart::kAxis);
    io::draw_text(img, 6, y.pixel(yv) - 3, label(yv), io::chart::kAxis);
    io::draw_line(img, x.pixel(xv), kHeight - kBottom, x.pixel(xv), kHeight - kBottom + 4, io::chart::kAxis);
    io::draw_line(img, kLeft - 4, y.pixel(yv), kLeft, y.pixel(yv), io::chart::kAxis);
  }
}

// Whether each point is joined to the one before it: a law may list several series one after the other (a
// swell's depths, then the next swell's), each running one way along x; a step back along x, or none, starts
// the next series.
std::vector<bool> series_joins(const std::vector<LawPoint>& points) {
  std::vector<bool> joined(points.size(), false);
  for (size_t i = 1; i < points.size(); ++i) {
    const double dx = points[i].x - points[i - 1].x;
    joined[i] = dx != 0 && (!joined[i - 1] || (dx > 0) == (points[i - 1].x > points[i - 2].x));
  }
  return joined;
}

}  // namespace

io::Image8 law_plot(const Law& law) {
  io::Image8 img{.width = kWidth, .height = kHeight};
  img.rgba.assign(size_t{kWidth} * kHeight * 4, 255);
  io::fill_rect(img, 0, 0, kWidth, kHeight, io::chart::kBackground);
  std::vector<double> xs, ys;
  for (const LawPoint& p : law.points) {
    xs.push_back(p.x);
    for (double v : {p.reference, p.measured, p.low, p.high})
      if (std::abs(v) < 1e200) ys.push_back(v);
  }
  const Axis x = fit(xs, law.log_x, kLeft, kWidth - kRight);
  const Axis y = fit(ys, law.log_y, kHeight - kBottom, kTop);
  const std::vector<bool> joined = series_joins(law.points);
  // The tolerance band: a column per point, joined to its neighbours in its series.
  for (size_t i = 0; i < law.points.size(); ++i) {
    const LawPoint& p = law.points[i];
    const double lo = p.low < -1e200 ? y.lo : p.low, hi = p.high > 1e200 ? y.hi : p.high;
    const int x0 = joined[i] ? (x.pixel(law.points[i - 1].x) + x.pixel(p.x)) / 2 : x.pixel(p.x) - 3;
    const int x1 = i + 1 < law.points.size() && joined[i + 1]
                       ? (x.pixel(p.x) + x.pixel(law.points[i + 1].x)) / 2
                       : x.pixel(p.x) + 3;
    io::fill_rect(img, x0, y.pixel(hi), std::max(x1 - x0, 1), std::max(y.pixel(lo) - y.pixel(hi), 1), kBand);
  }
  io::draw_line(img, kLeft, kHeight - kBottom, kWidth - kRight, kHeight - kBottom, io::chart::kAxis);
  io::draw_line(img, kLeft, kHeight - kBottom, kLeft, kTop, io::chart::kAxis);
  ticks(img, x, y);
  for (size_t i = 1; i < law.points.size(); ++i)
    if (joined[i])
      io::draw_line(img, x.pixel(law.points[i - 1].x), y.pixel(law.points[i - 1].reference),
                    x.pixel(law.points[i].x), y.pixel(law.points[i].reference), kReference);
  for (const LawPoint& p : law.points) {
    io::fill_rect(img, x.pixel(p.x) - 1, y.pixel(p.reference) - 1, 3, 3, kReference);
    io::fill_rect(img, x.pixel(p.x) - 3, y.pixel(p.measured) - 3, 7, 7, p.holds() ? kHolds : kFails);
  }
  io::draw_text(img, 8, 6, ascii(law.title), io::chart::kText, 2);
  int at = io::draw_text(img, 8, 28, "law (line): " + ascii(law.source) + "   ", kReference);
  at += io::draw_text(img, 8 + at, 28, "Lagoon (dots)  ", kHolds);
  io::draw_text(img, 8 + at, 28, "tolerance " + ascii(law.tolerance) + " (band)", io::chart::kDim);
  io::draw_text(img, kLeft, kHeight - 16, ascii(law.x_label) + (law.log_x ? " (log)" : ""), io::chart::kText);
  const std::string y_text = "y: " + ascii(law.y_label) + (law.log_y ? " (log)" : "");
  io::draw_text(img, kWidth - 8 - io::text_size(y_text).at(0), kHeight - 16, y_text, io::chart::kText);
  return img;
}

}  // namespace lagoon::cli
