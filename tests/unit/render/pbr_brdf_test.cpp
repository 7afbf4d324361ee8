// The glTF reference BRDF and its environment term (shared/pbr.h, one formula for the mesh shader and C++),
// against an independent double-precision evaluation written from the papers (Heitz 2014's Λ form of the
// height-correlated Smith term, not the glTF spec's rearranged one), against numerical integrals over the
// hemisphere, and in the white furnace. The environment's pre-filtered sky (render/environment_map.h) is
// checked against the sky's known irradiance.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "render/dfg_table.h"
#include "render/environment_map.h"
#include "render/sky_light.h"
#include "shared/pbr.h"

namespace lagoon {
namespace {

using glm::dvec3;
using glm::vec3;

// ---- The independent reference (double) ----
double d_ref(double cos_h, double alpha) {
  const double c2 = cos_h * cos_h, t2 = (1 - c2) / c2, a2 = alpha * alpha;
  return a2 / (std::numbers::pi * c2 * c2 * (a2 + t2) * (a2 + t2));  // Walter et al. 2007, eq. 33
}
double lambda_ref(double cos_t, double alpha) {  // Smith Λ of GGX (Heitz 2014, eq. 72)
  const double t2 = (1 - cos_t * cos_t) / (cos_t * cos_t);
  return 0.5 * (-1 + std::sqrt(1 + alpha * alpha * t2));
}
dvec3 brdf_cos_ref(dvec3 n, dvec3 v, dvec3 l, dvec3 base, double metallic, double roughness) {
  const double nl = glm::dot(n, l), nv = glm::dot(n, v);
  if (nl <= 0 || nv <= 0) return dvec3(0);
  const dvec3 h = glm::normalize(l + v);
  const double alpha = std::max(roughness * roughness, 1e-3);
  const double g2 = 1.0 / (1.0 + lambda_ref(nv, alpha) + lambda_ref(nl, alpha));
  const dvec3 f0 = glm::mix(dvec3(0.04), base, metallic);
  const dvec3 f = f0 + (1.0 - f0) * std::pow(1 - glm::dot(v, h), 5.0);
  const dvec3 spec = f * d_ref(glm::dot(n, h), alpha) * g2 / (4 * nl * nv);
  // Fdez-Agüera 2019, eqs. 14-18: E_ss = A + B, F_avg = f0 + (1 − f0)/21.
  const glm::dvec2 ab(render::dfg_table().lookup(float(nv), float(roughness)));
  const dvec3 fss_ess = f0 * ab.x + ab.y;
  const double ems = 1 - ab.x - ab.y;
  const dvec3 f_avg = f0 + (1.0 - f0) / 21.0;
  const dvec3 fms_ems = fss_ess * f_avg * ems / (1.0 - ems * f_avg);
  const dvec3 diffuse = (1 - metallic) * base * (1.0 - fss_ess - fms_ems) / std::numbers::pi;
  return (spec + diffuse + fms_ems / std::numbers::pi) * nl;
}

glm::vec2 ab_at(vec3 n, vec3 v, float roughness) {
  return render::dfg_table().lookup(glm::dot(n, v), roughness);
}

vec3 in_plane(double theta) {  // a direction at polar angle theta from +y, in the x-y plane
  return vec3(float(std::sin(theta)), float(std::cos(theta)), 0.0f);
}

// ∫ over the hemisphere around +y of g(l) dω (midpoint rule in θ and φ).
template <typename F>
dvec3 hemisphere(F g, int n_theta = 256, int n_phi = 512) {
  dvec3 sum(0);
  const double dt = 0.5 * std::numbers::pi / n_theta, dp = 2 * std::numbers::pi / n_phi;
  for (int i = 0; i < n_theta; ++i) {
    const double t = (i + 0.5) * dt;
    for (int j = 0; j < n_phi; ++j) {
      const double p = (j + 0.5) * dp;
      const vec3 l(float(std::sin(t) * std::cos(p)), float(std::cos(t)), float(std::sin(t) * std::sin(p)));
      sum += dvec3(g(l)) * std::sin(t) * dt * dp;
    }
  }
  return sum;
}

TEST(PbrBrdf, MatchesAnIndependentDoubleEvaluation) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(0, 1);
  const vec3 n(0, 1, 0);
  for (int k = 0; k < 2000; ++k) {
    const vec3 v = in_plane(u(rng) * 1.5), l = glm::normalize(vec3(u(rng) - 0.5, u(rng), u(rng) - 0.5));
    const dvec3 base(u(rng), u(rng), u(rng));
    const double metallic = u(rng), roughness = 0.05 + 0.95 * u(rng);
    const vec3 got = gpu::pbr_brdf_cos(n, v, l, vec3(base), float(metallic), float(roughness),
                                       ab_at(n, v, float(roughness)));
    const dvec3 want = brdf_cos_ref(n, v, l, base, metallic, roughness);
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(got[c], want[c], 2e-3 * want[c] + 1e-6) << "case " << k << " channel " << c;
  }
}

TEST(PbrBrdf, DirectionalAlbedoOfWhiteSurfacesIsOne) {
  // Light from every direction of a uniform white sky, out towards v: a white surface returns all of it
  // (energy-conserving diffuse plus the multiply scattered specular), within the table's interpolation.
  // glTF's sample weighting of the diffuse by 1 − F(v·h) returned 1.33 at a grazing view (83°, roughness
  // 0.25) with the table off, and the single-scattering metal only 0.31 at roughness 1.
  for (double roughness : {0.2, 0.35, 0.5, 0.75, 1.0}) {
    for (double theta_v : {0.0, 0.7, 1.2, 1.45}) {
      const vec3 v = in_plane(theta_v), n(0, 1, 0);
      for (float metallic : {0.0f, 1.0f}) {
        const glm::vec2 ab = ab_at(n, v, float(roughness));
        const dvec3 albedo = hemisphere(
            [&](vec3 l) { return gpu::pbr_brdf_cos(n, v, l, vec3(1), metallic, float(roughness), ab); });
        // At 83° the narrow lobes fall between the integration grid's rows: 5 %.
        EXPECT_NEAR(albedo.x, 1.0, theta_v > 1.3 ? 0.05 : 0.02)
            << "roughness " << roughness << " view " << theta_v << " metal " << metallic;
      }
    }
  }
}

TEST(PbrBrdf, DirectionalAlbedoTableFollowsTheIntegral) {
  // ∫ f_spec cos = f0·A + B: f0 = 1 gives A + B, f0 = 0 gives B, integrated in double on a grid with the
  // independent lobe (the table importance-samples the shared one), at points between the table's texels.
  double worst = 0;
  for (double roughness : {0.2, 0.41, 0.6, 0.83, 1.0}) {
    for (double theta_v : {0.1, 0.5, 0.9, 1.2, 1.4}) {
      const dvec3 v(std::sin(theta_v), std::cos(theta_v), 0);
      auto spec = [&](double f0) {
        return hemisphere(
                   [&](vec3 l) {
                     const dvec3 ld(l), h = glm::normalize(ld + v);
                     const double alpha = roughness * roughness;
                     const double g2 = 1.0 / (1.0 + lambda_ref(v.y, alpha) + lambda_ref(ld.y, alpha));
                     const double f = f0 + (1 - f0) * std::pow(1 - glm::dot(v, h), 5.0);
                     return dvec3(f * d_ref(h.y, alpha) * g2 / (4 * v.y));
                   },
                   384, 768)
            .x;
      };
      const glm::vec2 ab = render::dfg_table().lookup(float(v.y), float(roughness));
      const double e1 = std::abs(ab.x + ab.y - spec(1.0)), e0 = std::abs(ab.y - spec(0.0));
      worst = std::max({worst, e1, e0});
      EXPECT_LT(e1, 0.015) << "roughness " << roughness << " view " << theta_v;
      EXPECT_LT(e0, 0.005) << "roughness " << roughness << " view " << theta_v;
    }
  }
  RecordProperty("worst_abs_error", std::to_string(worst));
}

TEST(PbrBrdf, WhiteFurnace) {
  // A white surface under a uniform white environment (prefiltered = irradiance/π = 1): the dielectric
  // returns 1 ± 2 % at every roughness and angle, the metal never more than that.
  for (float roughness = 0.0f; roughness <= 1.0f; roughness += 0.125f) {
    for (float n_dot_v = 0.02f; n_dot_v <= 1.0f; n_dot_v += 0.07f) {
      const glm::vec2 ab = render::dfg_table().lookup(n_dot_v, roughness);
      const vec3 dielectric = gpu::pbr_environment(ab, vec3(1), 0.0f, vec3(1), vec3(1));
      const vec3 metal = gpu::pbr_environment(ab, vec3(1), 1.0f, vec3(1), vec3(1));
      EXPECT_NEAR(dielectric.x, 1.0f, 0.02f) << roughness << " " << n_dot_v;
      EXPECT_LE(metal.x, 1.0f + 1e-5f) << roughness << " " << n_dot_v;
      EXPECT_GT(metal.x, 0.98f) << "metal loses energy at roughness " << roughness;
    }
  }
}

// The angle (radians) at which the highlight of a white metal, lit from `theta_l` and seen in the mirror
// direction, has fallen to half as the view turns away.
double highlight_half_width(float roughness) {
  const vec3 n(0, 1, 0), l = in_plane(-0.5);
  const glm::vec2 ab(1.0f, 0.0f);  // E_ss = 1: the single-scattering lobe alone
  const double peak = gpu::pbr_brdf_cos(n, in_plane(0.5), l, vec3(1), 1.0f, roughness, ab).x;
  for (double d = 0.0; d < 1.0; d += 1e-4)
    if (gpu::pbr_brdf_cos(n, in_plane(0.5 + d), l, vec3(1), 1.0f, roughness, ab).x < 0.5 * peak) return d;
  return 1.0;
}

TEST(PbrBrdf, HighlightWidensWithRoughnessAndOnlyMetalsTintIt) {
  double previous = 0;
  for (float roughness : {0.1f, 0.2f, 0.35f, 0.5f, 0.7f}) {
    const double width = highlight_half_width(roughness);
    EXPECT_GT(width, previous) << "roughness " << roughness;
    previous = width;
  }
  // In the mirror direction, a red metal's highlight is red (f0 = base colour); a red dielectric's green
  // channel is the same untinted highlight as a black dielectric's (f0 = 0.04 for every colour).
  const vec3 n(0, 1, 0), l = in_plane(-0.5), v = in_plane(0.5), red(0.9f, 0.05f, 0.05f);
  const glm::vec2 ab = ab_at(n, v, 0.3f);
  const vec3 metal = gpu::pbr_brdf_cos(n, v, l, red, 1.0f, 0.3f, ab);
  EXPECT_NEAR(metal.y / metal.x, 0.05 / 0.9, 0.01);
  const vec3 dielectric = gpu::pbr_brdf_cos(n, v, l, vec3(0.0f, 0.0f, 0.0f), 0.0f, 0.3f, ab);
  const vec3 red_dielectric = gpu::pbr_brdf_cos(n, v, l, vec3(0.9f, 0.0f, 0.0f), 0.0f, 0.3f, ab);
  EXPECT_NEAR(red_dielectric.y, dielectric.y, 1e-6f);
  EXPECT_GT(dielectric.y, 0.1f);  // the highlight is there
}

TEST(PbrEnvironment, EquirectangularLayoutRoundTrips) {
  for (float u = 0.01f; u < 1.0f; u += 0.07f) {
    for (float v = 0.01f; v < 1.0f; v += 0.07f) {
      const glm::vec2 back = gpu::env_uv(gpu::env_direction({u, v}));
      EXPECT_NEAR(back.x, u, 1e-4f);
      EXPECT_NEAR(back.y, v, 1e-4f);
    }
  }
  EXPECT_NEAR(gpu::env_direction({0.3f, 0.0f}).y, 1.0f, 1e-6f);  // v = 0: the zenith
}

TEST(PbrEnvironment, IrradianceLayerIsTheSkysKnownIrradiance) {
  // sky_radiance is, by its definition, the radiance of a uniform sky with the model's E_sky: an upward
  // surface's irradiance over π. The filtered layers' zenith row must reproduce it; the mirror layer holds
  // the sky itself; the sea below reflects only a few per cent.
  for (double elevation : {15.0, 45.0, 70.0}) {
    scene::Sun sun;
    sun.elevation_deg = elevation;
    const render::SkyLight light = render::sky_light(sun);
    const render::EnvironmentLayers env = render::prefilter_environment(light.sky_model, light.sun_direction);
    const uint32_t irradiance = LAGOON_ENV_LAYERS - 1;
    glm::vec3 top(0), bottom(0);
    for (uint32_t x = 0; x < env.width; ++x) {
      top += env.at(irradiance, x, 0) / float(env.width);
      bottom += env.at(irradiance, x, env.height - 1) / float(env.width);
    }
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(top[c], light.sky_radiance[c], 0.03 * light.sky_radiance[c]) << "elevation " << elevation;
      // A flat sea reflects 2-100 % by angle, weighted towards the bright horizon: 6.6 % of a uniform sky.
      EXPECT_LT(bottom[c], 0.25 * light.sky_radiance[c]);
      EXPECT_GT(bottom[c], 0.03 * light.sky_radiance[c]);
    }
    const glm::vec3 d = gpu::env_direction({(0.5f + 3) / env.width, (0.5f + 5) / env.height});
    const glm::vec3 sky = gpu::sky_model_rgb(light.sky_model, d, light.sun_direction);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(env.at(0, 3, 5)[c], sky[c], 1e-6f);
  }
}

}  // namespace
}  // namespace lagoon
