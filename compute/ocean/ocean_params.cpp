#include "ocean/ocean_params.h"

namespace lagoon::ocean {

const char* to_string(SpectrumType type) {
  switch (type) {
    case SpectrumType::Phillips:
      return "phillips";
    case SpectrumType::PiersonMoskowitz:
      return "pm";
    case SpectrumType::Jonswap:
      return "jonswap";
    case SpectrumType::Tma:
      return "tma";
    case SpectrumType::JonswapEq15:
      return "jonswap-eq15";
    case SpectrumType::PhillipsEq18:
      return "phillips-eq18";
  }
  return "?";
}

const char* to_string(Spreading spreading) {
  switch (spreading) {
    case Spreading::Cos2:
      return "cos2";
    case Spreading::Cos2s:
      return "cos2s";
    case Spreading::DonelanBanner:
      return "donelan-banner";
  }
  return "?";
}

std::vector<GerstnerWaveSpec> default_gerstner_waves() {
  std::vector<GerstnerWaveSpec> waves(3);
  waves[0] = {0.5, 40, 180, 0};
  waves[1] = {0.25, 17, 155, 70};
  waves[2] = {0.12, 8, -150, 200};
  return waves;
}

GerstnerSet::GerstnerSet() : waves(default_gerstner_waves()) {}

SinesSet::SinesSet() : waves(3) {
  waves[0] = {0.6, 30, 180, 2, 0};
  waves[1] = {0.3, 13, 140, 3, 0};
  waves[2] = {0.15, 7, -155, 1, 0};
}

// Three drops at different places and times: rings that meet, so a scene switched to springs shows waves.
SpringsParams::SpringsParams() : drops(3) {
  drops[0] = {10, 60, 0, 6, 0.4};
  drops[1] = {-40, 90, 5, 5, 0.3};
  drops[2] = {50, 40, 10, 8, 0.5};
}

const char* to_string(SurfaceModel model) {
  switch (model) {
    case SurfaceModel::Fft:
      return "fft";
    case SurfaceModel::Gerstner:
      return "gerstner";
    case SurfaceModel::Sines:
      return "sines";
    case SurfaceModel::Perlin:
      return "perlin";
    case SurfaceModel::Springs:
      return "springs";
  }
  return "?";
}

const char* to_string(GerstnerDispersion law) {
  switch (law) {
    case GerstnerDispersion::Deep:
      return "deep";
    case GerstnerDispersion::FiniteDepth:
      return "finite-depth";
    case GerstnerDispersion::Capillary:
      return "capillary";
  }
  return "?";
}

bool from_string(const std::string& name, SurfaceModel& out) {
  for (SurfaceModel m : kSurfaceModels)
    if (name == to_string(m)) return out = m, true;
  return false;
}

bool from_string(const std::string& name, GerstnerDispersion& out) {
  for (GerstnerDispersion d :
       {GerstnerDispersion::Deep, GerstnerDispersion::FiniteDepth, GerstnerDispersion::Capillary})
    if (name == to_string(d)) return out = d, true;
  return false;
}

bool from_string(const std::string& name, SpectrumType& out) {
  for (SpectrumType t : {SpectrumType::Phillips, SpectrumType::PiersonMoskowitz, SpectrumType::Jonswap,
                         SpectrumType::Tma, SpectrumType::JonswapEq15, SpectrumType::PhillipsEq18})
    if (name == to_string(t)) return out = t, true;
  return false;
}

bool from_string(const std::string& name, Spreading& out) {
  for (Spreading s : {Spreading::Cos2, Spreading::Cos2s, Spreading::DonelanBanner})
    if (name == to_string(s)) return out = s, true;
  return false;
}

}  // namespace lagoon::ocean
