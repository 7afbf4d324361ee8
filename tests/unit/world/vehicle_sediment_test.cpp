// The sediment buffer the frame draws (world/vehicle_sediment.h, shared/sediment.h): the reach boxes the
// shaders cull with hold every cloud's reach (centre ± √20 σ), the whole set's and each group's, so that
// culling never drops a cloud the loop would draw (tests/unit/physics/sediment_test.cpp shows a segment
// missing a box gets nothing from its clouds); and the groups are stretches of the AUV's stream, smaller than
// the whole, or they would cull nothing the whole box does not.
#include "world/vehicle_sediment.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "shared/sediment.h"
#include "support/shipped_scene.h"

namespace lagoon::test {
namespace {

bool holds(const glm::vec4& lo, const glm::vec4& hi, const gpu::SedimentPuffGpu& p) {
  const glm::vec3 c(p.centre_sigma),
      reach(std::sqrt(float(LAGOON_SEDIMENT_REACH2_SIGMA2)) * p.centre_sigma.w);
  return glm::all(glm::lessThanEqual(glm::vec3(lo), c - reach)) &&
         glm::all(glm::greaterThanEqual(glm::vec3(hi), c + reach));
}

TEST(VehicleSediment, TheBuffersBoxesHoldEveryCloudsReachAndTheGroupsAreStretchesOfIt) {
  const scene::Scene s = shipped_scene("harbour", {"sediment.current_mps=[0,0]"});
  auto sediment = world::VehicleSediment::create(s);
  ASSERT_TRUE(sediment) << sediment.error().message;
  gpu::SedimentHeader header{};
  std::vector<gpu::SedimentPuffGpu> puffs(LAGOON_MAX_SEDIMENT_PUFFS);
  const uint32_t kept = sediment->write(40.0, &header, puffs.data());
  ASSERT_GT(kept, 3u * LAGOON_SEDIMENT_GROUP) << "the AUV has stirred several groups' worth by 40 s";
  EXPECT_EQ(header.colour.w, float(kept));
  const glm::vec3 whole = glm::vec3(header.box_hi) - glm::vec3(header.box_lo);
  int smaller = 0;
  for (uint32_t i = 0; i < kept; ++i) {
    const uint32_t g = i / LAGOON_SEDIMENT_GROUP;
    EXPECT_TRUE(holds(header.box_lo, header.box_hi, puffs[i])) << "cloud " << i;
    EXPECT_TRUE(holds(header.group_lo[g], header.group_hi[g], puffs[i])) << "cloud " << i << ", group " << g;
  }
  for (uint32_t g = 0; g * LAGOON_SEDIMENT_GROUP < kept; ++g) {
    const glm::vec3 size = glm::vec3(header.group_hi[g]) - glm::vec3(header.group_lo[g]);
    smaller += size.x * size.z < 0.5f * whole.x * whole.z;
  }
  EXPECT_GE(smaller, 2) << "groups as wide as the whole stream cull nothing more";
  // The groups past the clouds are empty: nothing meets them.
  for (uint32_t g = (kept + LAGOON_SEDIMENT_GROUP - 1) / LAGOON_SEDIMENT_GROUP; g < LAGOON_SEDIMENT_GROUPS;
       ++g)
    EXPECT_GT(header.group_lo[g].x, header.group_hi[g].x) << "group " << g;
}

}  // namespace
}  // namespace lagoon::test
