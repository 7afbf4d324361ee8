#include "scene/ocean_block.h"

#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace lagoon::scene {
namespace {

// Names come from ocean::to_string so the file format and the rest of the code spell them one way.
template <typename E>
std::vector<std::pair<std::string, E>> named(std::span<const E> values) {
  std::vector<std::pair<std::string, E>> options;
  for (E v : values) options.emplace_back(ocean::to_string(v), v);
  return options;
}
template <typename E>
std::vector<std::pair<std::string, E>> named(std::initializer_list<E> values) {
  return named(std::span<const E>(values.begin(), values.size()));
}

void read_spectrum(ObjectReader& r, ocean::SpectrumParams& s) {
  using ocean::SpectrumType;
  r.choice("type", s.type,
           named({SpectrumType::Jonswap, SpectrumType::PiersonMoskowitz, SpectrumType::Phillips,
                  SpectrumType::Tma, SpectrumType::JonswapEq15, SpectrumType::PhillipsEq18}),
           "Wave spectrum: how wave energy is spread over wavelengths (see Ocean below).");
  r.number("wind_speed_mps", s.wind_speed_mps, Bounds::above_up_to(0, 60), "m/s",
           "Wind speed 10 m above the surface (U10); sets the wave height and the peak wavelength.");
  r.number("wind_direction_deg", s.wind_direction_deg, Bounds::between(0, 360), "deg",
           "Direction the wind blows towards, clockwise from north (-z) toward east (+x); 90 = toward east.");
  r.number("fetch_km", s.fetch_km, Bounds::above_up_to(0, 10000), "km",
           "Distance over which the wind has blown; a short fetch gives younger, smaller, shorter waves "
           "(jonswap, tma).");
  r.number("gamma", s.gamma, Bounds::between(1, 20), "",
           "Peak enhancement: how sharply energy gathers at the peak wavelength; 1 = the pm shape (jonswap, "
           "tma).");
  using ocean::Spreading;
  r.choice("spreading", s.spreading, named({Spreading::Cos2, Spreading::Cos2s, Spreading::DonelanBanner}),
           "Directional spreading: how wave energy fans out around the wind direction (see Ocean below).");
  r.number("swell", s.swell, Bounds::between(0, 1), "",
           "Swell: 0 = pure wind sea; toward 1 the crests of long waves get longer and more parallel.");
  r.number("small_wave_cutoff_m", s.small_wave_cutoff_m, Bounds::between(0, 10), "m",
           "Damping length l: the spectrum is multiplied by exp(-k²l²), removing waves much shorter than l; "
           "0 = none (phillips).");
  r.number("amplitude", s.amplitude, Bounds::above_up_to(0, 1), "",
           "A of phillips-eq18, P(k) = A exp(-1/(kL)^2) / k^4 |cos phi|^p (seed 001 eq. 18), as a density in "
           "k: Hs = 4 L sqrt(A C_p / 2), L = U^2/g, C_p the integral of |cos phi|^p (pi at p = 2).");
  r.number("directional_exponent", s.directional_exponent, Bounds::between(0, 64), "",
           "p of phillips-eq18's |cos phi|^p: higher = crests more parallel to each other; 2 in the "
           "document.");
}

// The dispersion law of an explicit-wave model (eqs. 7-9), as gerstner and sines both choose it.
void dispersion_choice(ObjectReader& r, ocean::GerstnerDispersion& value, std::string_view doc) {
  using ocean::GerstnerDispersion;
  r.choice("dispersion", value,
           named({GerstnerDispersion::Deep, GerstnerDispersion::FiniteDepth, GerstnerDispersion::Capillary}),
           doc);
}

void read_gerstner_wave(ObjectReader& r, ocean::GerstnerWaveSpec& w) {
  r.number("amplitude_m", w.amplitude_m, Bounds::between(0, 100), "m",
           "Amplitude A: the crest's height above the mean level.");
  r.number("wavelength_m", w.wavelength_m, Bounds::above_up_to(0, 100000), "m",
           "Wavelength 2 pi / k, exact: the waves are summed where they are drawn (docs/models.md).");
  r.number("direction_deg", w.direction_deg, Bounds::between(-360, 360), "deg",
           "Direction it travels toward, clockwise from north (-z) toward east (+x).");
  r.number("phase_deg", w.phase_deg, Bounds::between(-360, 360), "deg", "Phase phi of eq. 11.");
  r.number("steepness", w.steepness, Bounds::between(0, 1), "",
           "Q of eq. 11 for this wave: 0 = a sine, 1 = the document's circles; absent = ocean.choppiness. "
           "Q k A summed over the waves may not exceed 1 (no loops).");
}

void read_gerstner(ObjectReader& r, ocean::GerstnerSet& g) {
  r.array("waves", g.waves, 1, 64, read_gerstner_wave,
          "The waves of eq. 11 (seed 001), summed directly with their exact wavelengths; a wave without "
          "its own steepness takes choppiness as its Q, and Q k A summed over the waves may not exceed 1 "
          "(no loops).");
  r.integer(
      "spectrum_waves", g.spectrum_waves, Bounds::between(0, 64), "",
      "If > 0, this many waves sampled from ocean.spectrum replace waves: frequencies from 0.6 to 4 times "
      "the peak, amplitudes sqrt(2 S(omega) d omega) without a random factor (seed 001 eq. 13), "
      "directions from the spreading. They go through the cascades (one FFT, cheaper than a sum per pixel), "
      "each moved to the cascades' lattice, with choppiness as every Q.");
  dispersion_choice(
      r, g.dispersion,
      "How fast each wave travels: deep = sqrt(g k) (eq. 7), finite-depth = sqrt(g k tanh(k depth_m)) "
      "(eq. 8), capillary = sqrt(g k (1 + k^2 L^2)), L the capillary length (eq. 9).");
}

void read_sine_wave(ObjectReader& r, ocean::SineWaveSpec& w) {
  r.number("amplitude_m", w.amplitude_m, Bounds::between(0, 100), "m", "Amplitude A of eq. 2.");
  r.number("wavelength_m", w.wavelength_m, Bounds::above_up_to(0, 100000), "m",
           "Wavelength 2 pi / freq, exact: the waves are summed where they are drawn (docs/models.md).");
  r.number("direction_deg", w.direction_deg, Bounds::between(-360, 360), "deg",
           "Direction it travels toward, clockwise from north (-z) toward east (+x).");
  r.integer("steepness", w.steepness, Bounds::between(1, 8), "",
            "Exponent of eq. 2: 1 = a plain sine; higher gives sharper crests and flatter troughs (whole "
            "numbers, so the wave is exactly `steepness` harmonics).");
  r.number("phase_deg", w.phase_deg, Bounds::between(-360, 360), "deg",
           "Added to S (not in eq. 1): waves that all start at phase 0 crest together at the origin.");
}

void read_sines(ObjectReader& r, ocean::SinesSet& s) {
  r.array(
      "waves", s.waves, 1, 64, read_sine_wave,
      "The waves of eqs. 1-3 (seed 001); their sum less its mean level is the surface (needs choppiness 0).");
  r.integer("spectrum_waves", s.spectrum_waves, Bounds::between(0, 64), "",
            "If > 0, this many plain sines (steepness 1) sampled from ocean.spectrum replace waves, as "
            "gerstner.spectrum_waves samples them (through the cascades, on their lattice).");
  dispersion_choice(r, s.dispersion, "The phase speed of each wave, as gerstner.dispersion.");
}

void read_perlin(ObjectReader& r, ocean::PerlinParams& p) {
  r.number("amplitude_m", p.amplitude_m, Bounds::between(0, 100), "m",
           "Amplitude of the first octave's noise.");
  r.integer(
      "cells", p.cells, Bounds::between(1, 512), "",
      "Noise lattice cells of the first octave across the first cascade's patch (a whole number: it tiles).");
  r.integer("octaves", p.octaves, Bounds::between(1, 12), "", "Octaves summed, each finer by lacunarity.");
  r.number("persistence", p.persistence, Bounds::between(0, 1), "",
           "Amplitude ratio between one octave and the next.");
  r.integer("lacunarity", p.lacunarity, Bounds::between(2, 8), "",
            "Frequency ratio between one octave and the next (a whole number, so every octave tiles).");
}

void read_spring_drop(ObjectReader& r, ocean::SpringDrop& d) {
  r.number("x_m", d.x_m, Bounds::between(-1e6, 1e6), "m", "Where it falls: x (east).");
  r.number("z_m", d.z_m, Bounds::between(-1e6, 1e6), "m", "Where it falls: z (south; north is -z).");
  r.number("time_s", d.time_s, Bounds::between(0, 1e6), "s",
           "When it falls (within the step that holds it).");
  r.number("radius_m", d.radius_m, Bounds::above_up_to(0, 1e4), "m",
           "Standard deviation of the Gaussian patch it pushes down; a few node spacings or more.");
  r.number("speed_mps", d.speed_mps, Bounds::between(-100, 100), "m/s",
           "Downward speed it gives the node at its centre (negative lifts).");
}

void read_spring_gust(ObjectReader& r, ocean::SpringGust& g) {
  r.number("x_m", g.x_m, Bounds::between(-1e6, 1e6), "m", "Where it starts: x (east).");
  r.number("z_m", g.z_m, Bounds::between(-1e6, 1e6), "m", "Where it starts: z (south; north is -z).");
  r.number("time_s", g.time_s, Bounds::between(0, 1e6), "s", "When it starts.");
  r.number("duration_s", g.duration_s, Bounds::between(0, 1e6), "s", "How long it blows.");
  r.number("radius_m", g.radius_m, Bounds::above_up_to(0, 1e4), "m",
           "Standard deviation of the Gaussian patch it presses on.");
  r.number("force_n", g.force_n, Bounds::between(-1e4, 1e4), "N",
           "Downward force on the node at its centre.");
  r.number("direction_deg", g.direction_deg, Bounds::between(-360, 360), "deg",
           "Direction it moves toward, clockwise from north (-z) toward east (+x).");
  r.number("speed_mps", g.speed_mps, Bounds::between(0, 100), "m/s", "How fast the patch moves.");
}

void read_springs(ObjectReader& r, ocean::SpringsParams& s) {
  r.number("mass_kg", s.mass_kg, Bounds::above_up_to(0, 1e6), "kg",
           "Mass m of a node (eq. 5; 4 in Table 1).");
  r.number(
      "stiffness_n_per_m", s.stiffness_n_per_m, Bounds::above_up_to(0, 1e6), "N/m",
      "Stiffness c of a spring (eq. 4; 7 in Table 1). Waves travel at sqrt(c/m) node spacings per second.");
  r.number("damping_kg_per_s", s.damping_kg_per_s, Bounds::between(0, 1e6), "kg/s",
           "Damping gamma (eq. 5; 0.05 in Table 1): the energy decays as exp(-gamma t / m).");
  r.number("step_s", s.step_s, Bounds::above_up_to(0, 100), "s",
           "Time step dt (eq. 5; 0.4 in Table 1); must stay below 2 / sqrt(8 c / m), 0.535 s for Table 1.");
  r.number("rest_length", s.rest_length, Bounds::between(0, 0.99), "",
           "Rest length L of eq. 4 as a fraction of the node spacing: 0 = linear springs; larger values make "
           "the springs slack at rest (slower, nonlinear waves).");
  r.array("drops", s.drops, 0, 64, read_spring_drop,
          "Drops: a push down on the water at a place and time. Drops and gusts together: at most 64.");
  r.array("gusts", s.gusts, 0, 64, read_spring_gust, "Wind gusts: a moving patch of pressure for a while.");
  r.number("boundary_amplitude_m", s.boundary_amplitude_m, Bounds::between(0, 100), "m",
           "Driven boundary: the nodes of the column x = 0 move as amplitude sin(2 pi t / period); 0 = off.");
  r.number("boundary_period_s", s.boundary_period_s, Bounds::above_up_to(0, 3600), "s",
           "Period of the driven boundary.");
}

void read_cascade(ObjectReader& r, ocean::CascadeParams& c) {
  r.number("patch_size_m", c.patch_size_m, Bounds::above_up_to(0, 100000), "m",
           "Side of the square tile this cascade's waves repeat over.");
  r.power_of_two(
      "resolution", c.resolution, 64, 1024, "",
      "Samples per tile side (FFT size N); the shortest wave it holds is 2 * patch_size_m / N long.");
}

void read_foam(ObjectReader& r, ocean::FoamParams& f) {
  // A scene that sets a threshold and no coverage means the threshold rule it was written for.
  if (r.has("threshold") && !r.has("coverage")) f.coverage = ocean::FoamCoverage::Threshold;
  r.choice("coverage", f.coverage,
           {{"monahan", ocean::FoamCoverage::Monahan}, {"threshold", ocean::FoamCoverage::Threshold}},
           "How much of the sea the whitecaps cover: monahan = the share Monahan & O'Muircheartaigh (1980) "
           "observed at the wind speed, 3.84e-6 U10^3.41 (0.2 % at 6 m/s, 7 % at 18 m/s), as the foam lasts, "
           "from each cascade's own Jacobian; threshold = where the Jacobian falls below `threshold` (the "
           "default when a scene sets `threshold`).");
  r.number("threshold", f.threshold, Bounds::between(-1, 2), "",
           "coverage threshold: foam forms where the surface Jacobian J (1 = flat, < 1 squeezed, <= 0 folded "
           "over) is below this, at rate clamp(threshold - J, 0, 1); higher = more foam.");
  r.number("decay_per_s", f.decay_per_s, Bounds::between(0, 100), "1/s",
           "How fast foam fades: as (foam + 0.4) exp(-decay_per_s * t) - 0.4, to nothing within "
           "ln(3.5)/decay_per_s seconds (4.2 s at 0.3); 0 = foam never fades.");
}

}  // namespace

void read_ocean(ObjectReader& r, ocean::OceanParams& o) {
  r.integer("seed", o.seed, Bounds::between(0, 4294967295.0), "",
            "Random seed of the wave amplitudes and phases; the same seed and fields give the same sea.");
  r.number(
      "depth_m", o.depth_m, Bounds::above_up_to(0, 11000), "m",
      "Water depth: slows long waves (finite-depth dispersion) and shapes the tma spectrum; a few hundred "
      "metres and more is deep water for all but the longest swell.");
  r.number("choppiness", o.choppiness, Bounds::between(0, 5), "",
           "Horizontal displacement scale: sharpens crests and widens troughs; 0 = points only move up and "
           "down, large values fold crests over (which makes foam).");
  r.number("loop_period_s", o.loop_period_s, Bounds::between(0, 3600), "s",
           "If > 0, wave frequencies are rounded so the whole sea repeats exactly with this period (seamless "
           "loops); 0 = no loop.");
  r.array("swell_waves", o.swell_waves, 0, 16, read_gerstner_wave,
          "Swell trains over the random sea (models fft and perlin): Gerstner waves with deep-water "
          "dispersion summed where they are drawn, which over the floor shoal, turn toward the shallows and "
          "break (docs/ocean.md, Waves over the floor); [] = none. Ignored by the models with their own "
          "waves.");
  r.flag(
      "shoaling", o.shoaling,
      "Waves feel the floor (docs/ocean.md, Waves over the floor): over it they shorten, slow, turn "
      "toward the shallows, grow and break where their height reaches breaker_index x depth, and end at "
      "the shoreline; the random sea's height is limited by the depth. false = the floor changes nothing.");
  r.number(
      "breaker_index", o.breaker_index, Bounds::between(0.3, 1.5), "",
      "Wave height over water depth at which waves break (McCowan's 0.78); the broken waves stay at it.");
  using ocean::SurfaceModel;
  r.choice(
      "model", o.model, named(std::span<const SurfaceModel>(ocean::kSurfaceModels)),
      "Surface model: fft = waves from the spectrum; gerstner = the waves listed in gerstner; sines = the "
      "sum of sines in sines (needs choppiness 0); perlin = octaves of gradient noise; springs = a grid of "
      "masses on springs on the first cascade, excited by drops, gusts or a driven boundary. Gerstner's and "
      "the sines' own waves are summed where they are drawn, the others go through the cascades "
      "(docs/models.md).");
  r.block("gerstner", o.gerstner, read_gerstner, "Model gerstner: its waves and dispersion.");
  r.block("sines", o.sines, read_sines, "Model sines: its waves and dispersion.");
  r.block("perlin", o.perlin, read_perlin, "Model perlin: its noise octaves.");
  r.block("springs", o.springs, read_springs,
          "Model springs: Table 1's constants and what excites the grid.");
  r.block("spectrum", o.spectrum, read_spectrum, "Wind and wave spectrum.");
  r.array("cascades", o.cascades, 1, 4, read_cascade,
          "FFT tiles from the largest patch to the smallest; each renders a band of wavelengths (see Ocean "
          "below). Given in a file, the array replaces the default list.");
  // Checked per neighbour pair so the error names the element to fix; the docs show it once on the
  // element row (the default list has 3 elements, so this loop also runs when describing).
  for (size_t i = 1; i < o.cascades.size(); ++i) {
    const double previous = o.cascades[i - 1].patch_size_m, current = o.cascades[i].patch_size_m;
    r.rule("cascades[" + std::to_string(i) + "].patch_size_m", current < previous, "< the previous cascade's",
           "got " + format_number(current) + " after " + format_number(previous) +
               "; list cascades from the largest patch to the smallest, each much smaller than the last "
               "(e.g. 1000, 100, 10)");
  }
  r.block("foam", o.foam, read_foam, "Whitecaps where waves fold over.");
}

}  // namespace lagoon::scene
