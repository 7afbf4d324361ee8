// lagoon bench effects: the evaluation of the MARS thesis (seed 002, §4.2-4.3, tables 4.3-4.7) for Lagoon's
// effects. A scripted camera flight (scene/camera_path.h) is flown once per configuration: no effects, each
// effect alone, all effects; each frame's wall time (render, submit, wait, readback) gives min/avg/max FPS
// and the passes' GPU timestamps their mean time. Reported as a table on stdout and, in --out, as
// effects.json, effects.csv, effects.md (laid out like the thesis's tables) and effects.png (a bar chart
// Lagoon draws).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "args.h"
#include "scene/scene.h"

namespace lagoon::cli {

// One configuration of the evaluation: a name and what it switches on over "no effects".
struct EffectConfig {
  std::string name;                          // "none", "reflection", ..., "all"
  std::string description;                   // for the tables
  std::function<void(scene::Scene&)> apply;  // on a scene with every effect off
};

// "none" (every effect off), each effect alone, "all" (every effect on, light shafts included).
const std::vector<EffectConfig>& effect_configs();
// The scene with every effect off, then `config` applied.
scene::Scene with_effects(const scene::Scene& scene, const EffectConfig& config);

int run_bench_effects(const ParsedArgs& args, long long width, long long height);

}  // namespace lagoon::cli
