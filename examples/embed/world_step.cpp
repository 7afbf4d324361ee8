// A host that steps what moves in a scene (its floating bodies and vehicles) with Lagoon::world alone: no
// Vulkan headers, no device (docs/embedding.md). It prints each body's and vehicle's pose after two
// seconds, as `lagoon probe --object NAME --time 2` does.
//   embed_world scenes/harbour.json
#include <cstdio>

#include "ocean/initial_spectrum.h"
#include "scene/scene.h"
#include "scene/scene_io.h"
#include "world/moving_pose.h"
#include "world/world.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: embed_world SCENE.json\n");
    return 2;
  }
  auto scene = lagoon::scene::load_scene(argv[1]);
  if (!scene) {
    std::fprintf(stderr, "embed_world: %s\n", scene.error().message.c_str());
    return 1;
  }
  auto world =
      lagoon::world::World::create(*scene, scene->ocean, lagoon::ocean::make_cascade_spectra(scene->ocean));
  if (!world) {
    std::fprintf(stderr, "embed_world: %s\n", world.error().message.c_str());
    return 1;
  }
  const double time_s = 2.0;
  (*world)->advance(time_s);
  for (const lagoon::world::MovingTarget& target : lagoon::world::moving_targets(*scene))
    std::printf("%s\n",
                lagoon::world::moving_pose(*scene, (*world)->bodies(), target, time_s).dump().c_str());
  return 0;
}
