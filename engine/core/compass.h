// Lagoon's one compass (issue 39): the world is right-handed with y up, east = +x, north = −z, so ENU is
// (x, −z, y). Azimuths and headings turn clockwise from north seen from above: 0 = north, 90 = east,
// 180 = south, 270 = west. Every angle a scene, a dataset, the demo or the physics states uses these
// functions to become a direction, so no two places can disagree about which way is east.
#pragma once
#include <cmath>
#include <numbers>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace lagoon::compass {

inline double radians(double degrees) {
  return degrees * (std::numbers::pi / 180.0);
}

// Unit horizontal vector (x, z) toward the azimuth `azimuth_rad`.
inline glm::dvec2 toward(double azimuth_rad) {
  return {std::sin(azimuth_rad), -std::cos(azimuth_rad)};
}
// In degrees, exact at the cardinal points (a wind toward 90 has no z part at all, as a direction written
// by hand means): the angle is reduced to the nearest multiple of 90 first, and only the rest goes through
// sin and cos.
inline glm::dvec2 toward_deg(double azimuth_deg) {
  const double quarter = std::round(azimuth_deg / 90.0);
  const glm::dvec2 rest = toward(radians(azimuth_deg - 90.0 * quarter));
  switch (((long long)quarter % 4 + 4) % 4) {  // turn `rest` by quarter × 90° clockwise: (x, z) -> (-z, x)
    case 1:
      return {-rest.y, rest.x};
    case 2:
      return {-rest.x, -rest.y};
    case 3:
      return {rest.y, -rest.x};
    default:
      return rest;
  }
}

// Unit world direction at a compass azimuth and an angle above the horizon (degrees): the sun's direction,
// a camera's view from yaw and pitch. In double, so an elevation of ±90 leaves x and z at ~1e-17.
inline glm::dvec3 direction_deg(double azimuth_deg, double elevation_deg) {
  const double elevation = radians(elevation_deg);
  const glm::dvec2 across = toward_deg(azimuth_deg) * std::cos(elevation);
  return {across.x, std::sin(elevation), across.y};
}

// Azimuth (rad, in [−π, π]) of the horizontal direction (x, z); the inverse of toward().
inline double azimuth_of(glm::dvec2 xz) {
  return std::atan2(xz.x, -xz.y);
}

// The right-handed angle about +y that turns a model's front (+z, glTF's forward) to face `azimuth_rad`:
// the heading grows clockwise seen from above, the angle about +y counterclockwise.
inline double angle_about_up(double azimuth_rad) {
  return std::numbers::pi - azimuth_rad;
}

}  // namespace lagoon::compass
