#include "plots.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "ocean/spectrum.h"
#include "ocean/spreading.h"

namespace lagoon::demo {

void spectrum_plots(const ocean::OceanParams& params) {
  const double wp = ocean::peak_omega(params.spectrum);
  // S(ω) from ω_p/3 to 6 ω_p on a log axis, where almost all the energy is.
  constexpr int kSamples = 160;
  std::vector<float> s(kSamples), d(kSamples);
  double m0 = 0, previous_w = 0;
  for (int i = 0; i < kSamples; ++i) {
    const double w = wp / 3.0 * std::pow(18.0, double(i) / (kSamples - 1));
    s[i] = float(ocean::frequency_spectrum(params.spectrum, params.depth_m, w));
    if (i > 0) m0 += 0.5 * (s[i] + s[i - 1]) * (w - previous_w);
    previous_w = w;
    const double theta = -std::numbers::pi + 2.0 * std::numbers::pi * i / (kSamples - 1);
    d[i] = float(ocean::spreading(params.spectrum, wp, theta));
  }
  const float s_max = *std::max_element(s.begin(), s.end());
  char overlay[96];
  std::snprintf(overlay, sizeof overlay, "S(w), w = wp/3 .. 6 wp (log axis); wp %.3g rad/s, Hs %.2f m", wp,
                4.0 * std::sqrt(m0));
  ImGui::PlotLines("##spectrum", s.data(), kSamples, 0, overlay, 0.0f, s_max * 1.1f, ImVec2(0, 90));
  const float d_max = *std::max_element(d.begin(), d.end());
  ImGui::PlotLines("##spreading", d.data(), kSamples, 0,
                   "D(wp, theta), theta = -180 .. 180 deg from the wind", 0.0f, d_max * 1.1f, ImVec2(0, 70));
}

namespace {

// One LUT as coloured cells: rows are h (depth) growing downwards, columns r (distance).
void lut_image(const char* title, const optics::WaterLut& lut, int channels, bool premultiply_a) {
  const float* data = channels == 4 ? lut.t0.data() : lut.t1.data();
  float peak = 1e-6f;
  for (uint32_t i = 0; i < lut.r_count * lut.h_count; ++i)
    for (int c = 0; c < 3; ++c) peak = std::max(peak, data[size_t(i) * channels + c]);
  ImGui::TextUnformatted(title);
  const float cell = 3.0f;
  const uint32_t step = std::max(1u, lut.r_count / 48);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  for (uint32_t h = 0; h < lut.h_count; h += step) {
    for (uint32_t r = 0; r < lut.r_count; r += step) {
      const float* texel = data + (size_t(r) * lut.h_count + h) * channels;
      const float a = premultiply_a ? texel[3] : 1.0f;
      auto encode = [&](float v) {
        return int(255.0f * std::pow(std::clamp(v * a / peak, 0.0f, 1.0f), 1 / 2.2f));
      };
      const ImVec2 p0(origin.x + float(r / step) * cell, origin.y + float(h / step) * cell);
      draw->AddRectFilled(p0, ImVec2(p0.x + cell, p0.y + cell),
                          IM_COL32(encode(texel[0]), encode(texel[1]), encode(texel[2]), 255));
    }
  }
  ImGui::Dummy(
      ImVec2(cell * float((lut.r_count + step - 1) / step), cell * float((lut.h_count + step - 1) / step)));
}

}  // namespace

void lut_images(const optics::WaterLut& lut) {
  if (lut.r_count == 0) return;
  lut_image("T0 * a (the bottom through the water); r ->, h down", lut, 4, true);
  ImGui::SameLine();
  ImGui::BeginGroup();
  lut_image("T1 (water colour)", lut, 3, false);
  ImGui::EndGroup();
  const auto& d = lut.deep_colour;
  ImGui::Text("deep water: %.3f %.3f %.3f", d.x, d.y, d.z);
  ImGui::TextDisabled("(linear sRGB relative to the light above the water; images scaled to their maximum)");
}

void pass_time_bars(const std::vector<vk::PassTime>& timings) {
  double total = 0;
  for (const vk::PassTime& t : timings) total += t.ms;
  for (const vk::PassTime& t : timings) {
    char label[64];
    std::snprintf(label, sizeof label, "%.1f ms", t.ms);
    ImGui::ProgressBar(total > 0 ? float(t.ms / total) : 0.0f, ImVec2(140, 0), label);
    ImGui::SameLine();
    ImGui::TextUnformatted(t.name.c_str());
  }
  ImGui::Text("GPU total %.1f ms", total);
}

void frame_time_graph(const std::deque<float>& frame_ms) {
  if (frame_ms.empty()) return;
  std::vector<float> values(frame_ms.begin(), frame_ms.end());
  std::vector<float> sorted = values;
  std::sort(sorted.begin(), sorted.end());
  char overlay[64];
  std::snprintf(overlay, sizeof overlay, "frame: median %.1f ms, last %.1f ms", sorted[sorted.size() / 2],
                values.back());
  ImGui::PlotLines("##frames", values.data(), int(values.size()), 0, overlay, 0.0f, sorted.back() * 1.2f,
                   ImVec2(0, 60));
}

}  // namespace lagoon::demo
