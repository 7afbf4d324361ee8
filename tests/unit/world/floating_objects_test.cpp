// Floating objects in scenes (objects[].floating; engine/world/floating_objects.h): the shipped buoy rides
// the default scene's sea, a frame's time gives the same poses however it is reached, a mesh that
// encloses nothing is refused with the field named, and a buoy too dense to float rests on the harbour's
// floor (issue 33).
#include "world/floating_objects.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <vector>

#include "ocean/local_heights.h"
#include "ocean/wave_query.h"
#include "support/gltf_quads.h"
#include "support/shipped_scene.h"
#include "support/temp_dir.h"
#include "world/floor_height.h"
#include "world/vehicle_sediment.h"
#include "world/vehicle_tracks.h"
#include "world/vehicle_wakes.h"

namespace lagoon::test {
namespace {

const std::string kFloatingBuoy =
    R"(objects=[{"file":"assets/buoy.gltf","position":[2,0,12],"floating":{"enabled":true,"density_kg_m3":400,)"
    R"("centre_of_mass_offset":[0,-0.6,0]}}])";

TEST(FloatingObjects, TheBuoyRidesTheScenesSea) {
  const scene::Scene s = shipped_scene("default", {kFloatingBuoy});
  const auto spectra = ocean::make_cascade_spectra(s.ocean);
  auto floating = world::FloatingObjects::create(s, s.ocean, spectra);
  ASSERT_TRUE(floating) << floating.error().message;
  ASSERT_FALSE((*floating)->empty());
  ocean::WaveQuery query(s.ocean, spectra);
  std::vector<double> heave, water;
  for (int i = 0; i <= 60; ++i) {
    const double t = 4.0 + 0.1 * i;
    (*floating)->advance(t);
    const physics::FloatingBody* body = (*floating)->body(0);
    ASSERT_NE(body, nullptr);
    const glm::dvec3 origin = body->model_origin();
    heave.push_back(origin.y);
    EXPECT_GT((body->state().orientation * glm::dvec3(0, 1, 0)).y, 0.9) << "it tipped over at " << t << " s";
    water.push_back(query.sample(t, origin.x, origin.z).height);
  }
  double mh = 0, mw = 0;
  for (size_t i = 0; i < heave.size(); ++i) mh += heave[i] / heave.size(), mw += water[i] / water.size();
  double sxy = 0, sxx = 0, syy = 0;
  for (size_t i = 0; i < heave.size(); ++i) {
    sxy += (heave[i] - mh) * (water[i] - mw);
    sxx += (heave[i] - mh) * (heave[i] - mh);
    syy += (water[i] - mw) * (water[i] - mw);
  }
  const double correlation = sxy / std::sqrt(sxx * syy);
  RecordProperty("correlation", std::to_string(correlation));
  RecordProperty("origin_above_water_m", std::to_string(mh - mw));
  // It moves with the waves, and its origin (the design waterline) rides above the water by what
  // Archimedes says for 400 kg/m³: the buoy's solids hold 1.462 m³ (tools/gen_assets.py), so 585 kg
  // displace 0.571 m³, 0.505 m of the 0.6 m float (1.131 m²) from its bottom at -0.8 m: the water at
  // -0.295 m in the model. Ballast 0.6 m down keeps it upright (as a uniform solid its weight is too high:
  // it capsizes, as such a buoy would).
  EXPECT_GT(correlation, 0.8);
  EXPECT_NEAR(mh - mw, 0.295, 0.03);
  EXPECT_GT(std::sqrt(sxx / heave.size()), 0.01);
}

// The demo's helm orders a vehicle's track; its body, its wake and the sediment it stirs all follow the
// order, because they share the track (world/vehicle_tracks.h).
TEST(FloatingObjects, ASteeredVehiclesBodyWakeAndSedimentFollowItsTrack) {
  const scene::Scene s = shipped_scene("harbour", {"sediment.current_mps=[0,0]"});
  world::VehicleTracks tracks = world::vehicle_tracks(s);
  ASSERT_EQ(tracks.size(), 2u);  // the boat, the AUV
  tracks[0]->order(2.0, {8.0, -0.3});
  tracks[1]->order(2.0, {1.5, 0.4});
  auto floating = world::FloatingObjects::create(s, s.ocean, ocean::make_cascade_spectra(s.ocean), tracks);
  auto wakes = world::VehicleWakes::create(s, tracks);
  auto sediment = world::VehicleSediment::create(s, tracks);
  ASSERT_TRUE(floating && wakes && sediment);
  ASSERT_FALSE(sediment->empty());
  const double t = 9.0;
  (*floating)->advance(t);
  for (size_t v = 0; v < 2; ++v) {
    const glm::dvec3 origin = (*floating)->vehicle(v).model_origin();
    const glm::dvec2 on_track = tracks[v]->at(t).position;
    EXPECT_NEAR(glm::distance(glm::dvec2(origin.x, origin.z), on_track), 0.0, 1e-6) << "vehicle " << v;
  }
  const auto sources = wakes->sources(t);
  ASSERT_EQ(sources.size(), 2u);
  for (size_t i = 0; i < sources.size(); ++i)
    EXPECT_NEAR(glm::distance(sources[i].centre, tracks[wakes->vehicle_of(i)]->at(t).position), 0.0, 1e-12);
  // The AUV's clouds lie where its track had it when each was released (no current, so they only sink).
  int steered = 0;
  for (const physics::SedimentPuff& p : sediment->puffs(t)) {
    const glm::dvec2 at_release = tracks[1]->at(t - p.age_s).position;
    EXPECT_NEAR(glm::distance(glm::dvec2(p.centre.x, p.centre.z), at_release), 0.0, 1e-6);
    steered += t - p.age_s > 2.5;
  }
  EXPECT_GT(steered, 3) << "clouds released after the order";
  // And the fresh path is somewhere else by then.
  EXPECT_GT(glm::distance(world::vehicle_tracks(s)[1]->at(t).position, tracks[1]->at(t).position), 1.0);
}

TEST(FloatingObjects, AnEarlierTimeIsSimulatedAgainFromZero) {
  const scene::Scene s = shipped_scene("default", {kFloatingBuoy});
  const auto spectra = ocean::make_cascade_spectra(s.ocean);
  auto a = world::FloatingObjects::create(s, s.ocean, spectra);
  auto b = world::FloatingObjects::create(s, s.ocean, spectra);
  ASSERT_TRUE(a && b);
  (*a)->advance(3.0);
  (*a)->advance(1.5);  // back in time
  (*b)->advance(1.5);
  const auto pa = (*a)->poses(), pb = (*b)->poses();
  ASSERT_EQ(pa.size(), 1u);
  EXPECT_EQ(0, std::memcmp(&pa[0].model_to_world, &pb[0].model_to_world, sizeof(glm::mat4)));
}

// A hull looks its water up once a point: the wakes are added to its lattice of the sea's heights where the
// hull can reach (issue 35). What it feels must still be the sea (WaveQuery without the waves the lattice
// leaves out) plus every wake but its own vehicle's, wherever its points are, while the boat's wake passes
// the buoy and the moored boat and the AUV's passes the boat. Leaving the wakes out misses them by far more.
TEST(FloatingObjects, AHullFeelsTheSeaAndTheOtherWakesAtEachOfItsPoints) {
  const scene::Scene s = shipped_scene("harbour");
  const auto spectra = ocean::make_cascade_spectra(s.ocean);
  auto floating = world::FloatingObjects::create(s, s.ocean, spectra);
  ASSERT_TRUE(floating) << floating.error().message;
  const world::WakeHeights* wakes = (*floating)->wakes();
  ASSERT_NE(wakes, nullptr);
  ocean::WaveQuery sea(
      s.ocean, spectra,
      ocean::WaveQueryOptions{.max_wavenumber = ocean::lattice_wavenumber({}), .heights_only = true});
  const size_t boat = s.objects.size();  // vehicles[0]: the boat, on the surface
  double worst = 0, largest_wake = 0;
  for (double t = 4.0; t <= 16.0; t += 1.5) {
    (*floating)->advance(t);
    const double felt_at = (std::floor(t * 120 + 1e-9) - 1) / 120;  // the last step's start
    for (size_t object : {size_t{0}, size_t{1}, boat}) {
      const physics::FloatingBody* hull = (*floating)->hull_body(object);
      ASSERT_NE(hull, nullptr) << object;
      std::vector<glm::dvec2> points;
      for (const glm::dvec3& p : hull->sample_points_in_world()) points.push_back({p.x, p.z});
      const std::vector<double> felt = (*floating)->water_under(object, points);
      const std::vector<ocean::WaveSample> waves = sea.sample(felt_at, points);
      const size_t own = object == boat ? 0 : world::WakeHeights::kNoVehicle;
      for (size_t i = 0; i < points.size(); ++i) {
        const double wake = wakes->height(points[i], own);
        worst = std::max(worst, std::abs(felt[i] - (waves[i].height + wake)));
        largest_wake = std::max(largest_wake, std::abs(wake));
      }
    }
  }
  // The sea's part is interpolated in time and space (ocean/local_heights.h: within 1 cm), the wakes' again
  // from the lattice's points.
  std::printf("hull's water against sea + wakes: worst %.4f m, largest wake under a hull %.3f m\n", worst,
              largest_wake);
  EXPECT_LT(worst, 0.012);
  EXPECT_GT(largest_wake, 0.05) << "a wake must pass under a hull for the check to see it";
}

// With bodies_start_s the bodies and vehicles start at rest where the scene puts them at that time, and are
// simulated from it: before it they stand there, after it they move, and an earlier time after a later one is
// simulated again from the start, not from 0 (issue 36: a late frame needs a late start).
TEST(FloatingObjects, ALateStartPutsThemAtRestThenAndSimulatesFromIt) {
  const scene::Scene late = shipped_scene("harbour", {"wakes.felt_by_bodies=false", "bodies_start_s=40"});
  const scene::Scene early = shipped_scene("harbour", {"wakes.felt_by_bodies=false"});
  const auto spectra = ocean::make_cascade_spectra(late.ocean);
  auto a = world::FloatingObjects::create(late, late.ocean, spectra);
  auto b = world::FloatingObjects::create(late, late.ocean, spectra);
  auto from_zero = world::FloatingObjects::create(early, early.ocean, spectra);
  ASSERT_TRUE(a && b && from_zero);
  EXPECT_DOUBLE_EQ((*a)->start_s(), 40.0);
  EXPECT_EQ((*a)->steps_to(41.0), 120);  // not 4920
  // Before the start: the floating objects where a start at 0 has them at 0, the boat where its path has it
  // at 40 s.
  (*a)->advance(30.0);
  (*from_zero)->advance(0.0);
  const auto pa = (*a)->poses(), p0 = (*from_zero)->poses();
  ASSERT_EQ(pa.size(), 4u);  // buoy, moored boat, boat, AUV
  for (size_t i = 0; i < 2; ++i)
    EXPECT_EQ(0, std::memcmp(&pa[i].model_to_world, &p0[i].model_to_world, sizeof(glm::mat4))) << i;
  const glm::dvec3 boat = (*a)->vehicle(0).model_origin();
  EXPECT_NEAR(glm::distance(glm::dvec2(boat.x, boat.z), (*a)->tracks()[0]->at(40.0).position), 0.0, 1e-9);
  // After it: the buoy moves from rest, afloat.
  const glm::dvec3 placed = (*a)->body(0)->model_origin();
  (*a)->advance(43.0);
  const physics::FloatingBody& buoy = *(*a)->body(0);
  EXPECT_GT(glm::length(buoy.state().velocity), 1e-3);
  EXPECT_NE(buoy.model_origin(), placed);
  EXPECT_NEAR(buoy.model_origin().y, 0.3, 0.6) << "the buoy sank or flew";
  // Back in time: from the start again, the bits of a fresh run.
  (*a)->advance(41.5);
  (*b)->advance(41.5);
  const auto back = (*a)->poses(), fresh = (*b)->poses();
  for (size_t i = 0; i < back.size(); ++i)
    EXPECT_EQ(0, std::memcmp(&back[i].model_to_world, &fresh[i].model_to_world, sizeof(glm::mat4))) << i;
}

// What a frame at a time costs in physics, the figure Python's render(time=) and World.advance hold to 300
// hull-seconds: the hulls (not the submerged AUV) times the seconds from where the bodies are.
TEST(FloatingObjects, HullSecondsToATimeCountFromWhereTheBodiesAre) {
  const scene::Scene s = shipped_scene("harbour", {"wakes.felt_by_bodies=false"});
  auto objects = world::FloatingObjects::create(s, s.ocean, ocean::make_cascade_spectra(s.ocean));
  ASSERT_TRUE(objects);
  EXPECT_NEAR((*objects)->hull_seconds_to(100.0), 300.0, 1e-9);  // buoy, moored boat and boat, from 0
  (*objects)->advance(1.0);
  EXPECT_NEAR((*objects)->hull_seconds_to(3.0), 6.0, 1e-9);  // on from 1 s
  EXPECT_NEAR((*objects)->hull_seconds_to(0.5), 1.5, 1e-9);  // back: from the start again
}

// The harbour's buoy at 20000 kg/m³ sinks to the slope floor (6 m down where it is) and stays there. The
// scene is cut to that one body, without the vehicles.
TEST(FloatingObjects, ABuoyTooDenseToFloatRestsOnTheHarbourFloor) {
  const scene::Scene s =
      shipped_scene("harbour", {R"(objects=[{"file":"assets/buoy.gltf","position":[2,0,12],)"
                                R"("floating":{"enabled":true,"density_kg_m3":20000}}])",
                                "vehicles=[]"});
  auto floating = world::FloatingObjects::create(s, s.ocean, ocean::make_cascade_spectra(s.ocean));
  ASSERT_TRUE(floating) << floating.error().message;
  auto floor = world::floor_height(s);
  ASSERT_TRUE(floor);
  (*floating)->advance(60.0);
  const physics::FloatingBody* body = (*floating)->body(0);
  ASSERT_NE(body, nullptr);
  // The buoy's model spans y from -0.8 m (tools/gen_assets.py): its bottom's depth against the floor's.
  const glm::dvec3 origin = body->model_origin();
  const double floor_y = (*floor)(origin.x, origin.z);
  RecordProperty("origin_y", std::to_string(origin.y));
  RecordProperty("floor_y", std::to_string(floor_y));
  EXPECT_LT(floor_y, -5.0);
  EXPECT_GT(origin.y - 0.8, floor_y - 0.05) << "it went through the floor";
  // Upright on the 1:8 slope its disc (radius 0.6 m) touches at its low rim: its centre 0.075 m higher.
  EXPECT_LT(origin.y - 0.8, floor_y + 0.15) << "it does not rest on the floor";
  EXPECT_LT(glm::length(body->state().velocity), 0.01);
  EXPECT_GT(body->last_floor_push().points, 0);
}

// What bodies rest on, for each kind of floor: the slope's closed form, a glTF floor's triangles (a 4 m
// square laid flat 7 m down; nothing beyond it), and with none the sea's depth.
TEST(FloatingObjects, TheFloorIsKnownOnTheCpuForEveryKindOfFloor) {
  scene::Scene s = shipped_scene("harbour", {});
  auto slope = world::floor_height(s);
  ASSERT_TRUE(slope);
  EXPECT_NEAR((*slope)(0.0, -30.0), -0.8, 1e-6);
  EXPECT_NEAR((*slope)(5.0, 200.0), -30.0, 1e-5);

  TempDir dir;
  write_quads(dir / "floor.gltf", {{.material = nlohmann::json::object(),
                                    .translation = {1, -7, 0},
                                    .rotation = {-0.70710678, 0, 0, 0.70710678}}});
  s.seafloor.type = scene::SeafloorType::Gltf;
  s.seafloor.file = (dir / "floor.gltf").string();
  auto mesh = world::floor_height(s);
  ASSERT_TRUE(mesh) << mesh.error().message;
  EXPECT_NEAR((*mesh)(0.5, 1.5), -7.0, 1e-5);
  EXPECT_NEAR((*mesh)(-0.9, -1.9), -7.0, 1e-5);
  EXPECT_EQ((*mesh)(3.5, 0.0), -std::numeric_limits<double>::infinity());

  s.seafloor.type = scene::SeafloorType::None;
  auto none = world::floor_height(s);
  ASSERT_TRUE(none);
  EXPECT_EQ((*none)(3.0, 4.0), -s.ocean.depth_m);
}

// Sediment is stirred over a glTF floor as over the slope (issue 39): the harbour's AUV (4.4 m down) over a
// level glTF floor at 5.2 m releases clouds that start from that floor, and the same floor 45 m down, far
// below the hull, stirs nothing.
TEST(FloatingObjects, AGltfFloorIsStirredAsTheSlopeIs) {
  TempDir dir;
  scene::Scene s = shipped_scene("harbour", {"sediment.current_mps=[0,0]"});
  s.seafloor.type = scene::SeafloorType::Gltf;
  auto puffs_over = [&](double floor_y) {
    const std::string file = (dir / ("floor" + std::to_string(int(-floor_y)) + ".gltf")).string();
    write_quads(file, {{.material = nlohmann::json::object(),
                        .translation = {0, floor_y, 6},
                        .rotation = {-0.70710678, 0, 0, 0.70710678},
                        .half = 100}});
    s.seafloor.file = file;
    auto sediment = world::VehicleSediment::create(s);
    EXPECT_TRUE(sediment) << sediment.error().message;
    return sediment ? sediment->puffs(10.0) : std::vector<physics::SedimentPuff>{};
  };
  const std::vector<physics::SedimentPuff> near = puffs_over(-5.2);
  ASSERT_GT(near.size(), 3u) << "the AUV passes 0.5 m over the floor";
  for (const physics::SedimentPuff& p : near) {
    // Thrown up to rise_m over the floor by the burst, then sinking at the settling speed.
    const double burst = 1 - std::exp(-p.age_s / s.sediment.burst_s);
    EXPECT_NEAR(p.centre.y, -5.2 + s.sediment.rise_m * burst - s.sediment.settling_mps * p.age_s, 1e-4);
  }
  EXPECT_TRUE(puffs_over(-45.0).empty()) << "a floor far below the hull is not stirred";
}

TEST(FloatingObjects, AMeshThatEnclosesNothingIsRefusedNamingTheField) {
  TempDir dir;
  std::ofstream(dir / "sheet.gltf")
      << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
      << R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
      << R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,0,1]}],)"
      << R"("bufferViews":[{"buffer":0,"byteLength":36}],"buffers":[{"byteLength":36,)"
      << R"("uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAAAAAAAAAAAAAIA/AACAPwAAAAAAAAAA"}]})";
  scene::Scene s = shipped_scene("default", {});
  s.objects = {scene::Object{.file = (dir / "sheet.gltf").string()}};
  s.objects[0].floating.enabled = true;
  auto floating = world::FloatingObjects::create(s, s.ocean, ocean::make_cascade_spectra(s.ocean));
  ASSERT_FALSE(floating);
  EXPECT_NE(floating.error().message.find("objects[0].floating"), std::string::npos)
      << floating.error().message;
  EXPECT_NE(floating.error().message.find("closed mesh"), std::string::npos) << floating.error().message;
}

}  // namespace
}  // namespace lagoon::test
