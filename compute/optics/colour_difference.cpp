#include "optics/colour_difference.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "optics/colour.h"

namespace lagoon::optics {
namespace {

double lab_f(double t) {
  constexpr double delta = 6.0 / 29.0;
  return t > delta * delta * delta ? std::cbrt(t) : t / (3 * delta * delta) + 4.0 / 29.0;
}

double degrees(double rad) {
  return rad * 180.0 / std::numbers::pi;
}
double radians(double deg) {
  return deg * std::numbers::pi / 180.0;
}

// Hue angle in degrees, [0, 360); 0 for a neutral colour (Sharma's convention).
double hue(double a, double b) {
  if (a == 0 && b == 0) return 0;
  const double h = degrees(std::atan2(b, a));
  return h < 0 ? h + 360 : h;
}

}  // namespace

glm::dvec3 xyz_to_lab(glm::dvec3 xyz, glm::dvec3 white_xyz) {
  const double fx = lab_f(xyz.x / white_xyz.x), fy = lab_f(xyz.y / white_xyz.y),
               fz = lab_f(xyz.z / white_xyz.z);
  return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}

glm::dvec3 linear_srgb_to_lab(glm::dvec3 linear_rgb) {
  return xyz_to_lab(linear_srgb_to_xyz() * linear_rgb, linear_srgb_to_xyz() * glm::dvec3(1.0));
}

double delta_e_2000(glm::dvec3 lab1, glm::dvec3 lab2) {
  const double c1 = std::hypot(lab1.y, lab1.z), c2 = std::hypot(lab2.y, lab2.z);
  const double c_mean7 = std::pow(0.5 * (c1 + c2), 7);
  const double g = 0.5 * (1 - std::sqrt(c_mean7 / (c_mean7 + std::pow(25.0, 7))));
  const double a1 = (1 + g) * lab1.y, a2 = (1 + g) * lab2.y;
  const double cp1 = std::hypot(a1, lab1.z), cp2 = std::hypot(a2, lab2.z);
  const double hp1 = hue(a1, lab1.z), hp2 = hue(a2, lab2.z);

  const double dl = lab2.x - lab1.x, dc = cp2 - cp1;
  double dh = 0;
  if (cp1 * cp2 != 0) {
    dh = hp2 - hp1;
    if (dh > 180) dh -= 360;
    if (dh < -180) dh += 360;
  }
  const double dhh = 2 * std::sqrt(cp1 * cp2) * std::sin(radians(dh / 2));

  const double l_mean = 0.5 * (lab1.x + lab2.x), cp_mean = 0.5 * (cp1 + cp2);
  double h_mean = hp1 + hp2;
  if (cp1 * cp2 != 0) {
    if (std::abs(hp1 - hp2) <= 180)
      h_mean = 0.5 * (hp1 + hp2);
    else
      h_mean = hp1 + hp2 < 360 ? 0.5 * (hp1 + hp2 + 360) : 0.5 * (hp1 + hp2 - 360);
  }
  const double t = 1 - 0.17 * std::cos(radians(h_mean - 30)) + 0.24 * std::cos(radians(2 * h_mean)) +
                   0.32 * std::cos(radians(3 * h_mean + 6)) - 0.20 * std::cos(radians(4 * h_mean - 63));
  const double d_theta = 30 * std::exp(-std::pow((h_mean - 275) / 25, 2));
  const double cp_mean7 = std::pow(cp_mean, 7);
  const double rc = 2 * std::sqrt(cp_mean7 / (cp_mean7 + std::pow(25.0, 7)));
  const double l50 = (l_mean - 50) * (l_mean - 50);
  const double sl = 1 + 0.015 * l50 / std::sqrt(20 + l50), sc = 1 + 0.045 * cp_mean,
               sh = 1 + 0.015 * cp_mean * t;
  const double rt = -std::sin(radians(2 * d_theta)) * rc;
  const double ql = dl / sl, qc = dc / sc, qh = dhh / sh;
  return std::sqrt(ql * ql + qc * qc + qh * qh + rt * qc * qh);
}

}  // namespace lagoon::optics
