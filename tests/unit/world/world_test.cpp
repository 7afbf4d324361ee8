// world::World (compute/world/world.h): one object for what moves in a scene. Its bodies, vehicles and
// sediment follow the tracks it was given (a host's helm reaches all of them), and it judges the camera's
// side only when asked to, against the waves' reach.
#include "world/world.h"

#include <gtest/gtest.h>

#include "ocean/initial_spectrum.h"
#include "support/shipped_scene.h"

namespace lagoon::test {
namespace {

TEST(World, ItsBodiesAndSedimentFollowTheTracksItWasGiven) {
  const scene::Scene s = shipped_scene("harbour", {"sediment.current_mps=[0,0]"});
  world::VehicleTracks tracks = world::vehicle_tracks(s);
  ASSERT_EQ(tracks.size(), 2u);  // the boat, the AUV
  tracks[0]->order(2.0, {8.0, -0.3});
  tracks[1]->order(2.0, {1.5, 0.4});
  auto made = world::World::create(s, s.ocean, ocean::make_cascade_spectra(s.ocean), {.tracks = tracks});
  ASSERT_TRUE(made) << made.error().message;
  world::World& w = **made;
  ASSERT_EQ(w.tracks().size(), 2u);
  EXPECT_EQ(w.tracks()[0], tracks[0]);  // shared, not copied: a later order reaches the world
  EXPECT_EQ(w.tracks()[1], tracks[1]);
  EXPECT_FALSE(w.has_camera_medium());

  const double t = 9.0;
  w.advance(t);
  for (size_t v = 0; v < 2; ++v) {
    const glm::dvec3 origin = w.bodies().vehicle(v).model_origin();
    EXPECT_NEAR(glm::distance(glm::dvec2(origin.x, origin.z), tracks[v]->at(t).position), 0.0, 1e-6)
        << "vehicle " << v;
  }
  ASSERT_FALSE(w.sediment().empty());
  int steered = 0;
  for (const physics::SedimentPuff& p : w.sediment().puffs(t)) {
    const glm::dvec2 at_release = tracks[1]->at(t - p.age_s).position;
    EXPECT_NEAR(glm::distance(glm::dvec2(p.centre.x, p.centre.z), at_release), 0.0, 1e-6);
    steered += t - p.age_s > 2.5;
  }
  EXPECT_GT(steered, 3) << "clouds released after the order";
  // A fresh world, on the scene's own paths, has the AUV elsewhere by then.
  auto fresh = world::World::create(s, s.ocean, ocean::make_cascade_spectra(s.ocean));
  ASSERT_TRUE(fresh);
  (*fresh)->advance(t);
  const glm::dvec3 a = (*fresh)->bodies().vehicle(1).model_origin(), b = w.bodies().vehicle(1).model_origin();
  EXPECT_GT(glm::distance(glm::dvec2(a.x, a.z), glm::dvec2(b.x, b.z)), 1.0);
}

TEST(World, WithACameraReachItJudgesTheCamerasSide) {
  const scene::Scene s = shipped_scene("harbour");
  auto made = world::World::create(s, s.ocean, ocean::make_cascade_spectra(s.ocean), {.camera_reach_m = 3.0});
  ASSERT_TRUE(made) << made.error().message;
  ASSERT_TRUE((*made)->has_camera_medium());
  world::CameraMedium& medium = (*made)->camera_medium();
  EXPECT_EQ(medium.side({0.f, 20.f, 0.f}, 0.05, 6.0), world::CameraSide::Above);
  EXPECT_EQ(medium.side({0.f, -20.f, 0.f}, 0.05, 6.0), world::CameraSide::Below);
  // Near the surface it asks the waves: the answer agrees with the surface's height there.
  const double h = medium.surface_height(3.0, 4.0, 6.0);
  EXPECT_EQ(medium.side({3.f, float(h + 0.5), 4.f}, 0.05, 6.0), world::CameraSide::Above);
  EXPECT_EQ(medium.side({3.f, float(h - 0.5), 4.f}, 0.05, 6.0), world::CameraSide::Below);
}

}  // namespace
}  // namespace lagoon::test
