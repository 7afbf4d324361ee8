// Parameters of the FFT ocean: what the scene's "ocean" block holds (docs/scene-format.md documents every
// field with its unit, default and range). Plain data, no Vulkan.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lagoon::ocean {

struct DepthProfile;  // ocean/depth_profile.h

inline constexpr double kGravity = 9.81;  // m/s²

// JonswapEq15 and PhillipsEq18 are the comparison document's own forms (seed 001, eqs. 14-15 and 17-18):
// JONSWAP on Pierson-Moskowitz's fully developed peak, and Tessendorf's Phillips spectrum in wavenumbers
// with its own amplitude and directional factor |cos φ|^p.
enum class SpectrumType { Phillips, PiersonMoskowitz, Jonswap, Tma, JonswapEq15, PhillipsEq18 };
enum class Spreading { Cos2, Cos2s, DonelanBanner };

struct SpectrumParams {
  SpectrumType type = SpectrumType::Jonswap;
  double wind_speed_mps = 10.0;       // U10, wind speed 10 m above the surface; > 0
  double wind_direction_deg = 180.0;  // direction the wind blows towards, compass degrees (core/compass.h)
  double fetch_km = 100.0;            // distance over which the wind has blown (JONSWAP, TMA); > 0
  double gamma = 3.3;                 // JONSWAP peak enhancement; 1 gives Pierson-Moskowitz's shape
  Spreading spreading = Spreading::Cos2s;
  double swell = 0.0;                // Horvath's swell ξ in [0, 1]: elongates crests of long waves
  double small_wave_cutoff_m = 0.0;  // Phillips' damping length l (exp(-k²l²)); 0 = none
  // phillips-eq18 only: P(k) = amplitude · exp(-1/(kL)²) / k⁴ · |cos φ|^directional_exponent, a density in k
  // (m⁴, so amplitude is dimensionless); the default gives the ω⁻⁵ tail of the other spectra at p = 2.
  double amplitude = 0.0081 / (2 * 3.14159265358979323846);
  double directional_exponent = 2.0;
  // JONSWAP and TMA: end fetch-limited growth at full development (ocean/spectrum.h, sea_development). false
  // applies the fetch laws at any fetch, as before issue 33: only `lagoon validate --broken` asks for it.
  bool cap_at_full_development = true;
};

// Which surface model makes the sea (issue 15, docs/models.md): the FFT ocean's random spectrum, or an
// explicit set of waves (Gerstner's or sines) evaluated directly where they are drawn (ocean/direct_waves.h).
enum class SurfaceModel { Fft, Gerstner, Sines, Perlin, Springs };
// Every model, in the order the docs, the scene format, the demo's selector and `lagoon bench` list them.
inline constexpr SurfaceModel kSurfaceModels[] = {SurfaceModel::Fft, SurfaceModel::Gerstner,
                                                  SurfaceModel::Sines, SurfaceModel::Perlin,
                                                  SurfaceModel::Springs};

// Gerstner waves' dispersion (seed 001): eq. 7 deep water, eq. 8 finite depth, eq. 9 capillary.
enum class GerstnerDispersion { Deep, FiniteDepth, Capillary };

struct GerstnerWaveSpec {
  double amplitude_m = 0.5;
  double wavelength_m = 20;
  double direction_deg = 180;  // travels toward, compass degrees
  double phase_deg = 0;
  std::optional<double>
      steepness;  // Q_i of eq. 11; none: ocean.choppiness (as every wave sampled from the spectrum)
};

// Three waves of a moderate swell (Σ k A = 0.37): what a scene switched to model gerstner starts with.
std::vector<GerstnerWaveSpec> default_gerstner_waves();

struct GerstnerSet {
  GerstnerSet();  // out of line: GCC 12 warns wrongly about an inlined vector default here
  std::vector<GerstnerWaveSpec> waves;
  GerstnerDispersion dispersion = GerstnerDispersion::Deep;
  // > 0: this many waves sampled from `spectrum` (deterministic amplitudes, seed 001 eq. 13) replace `waves`.
  uint32_t spectrum_waves = 0;
};

// A wave of the sum of sines (seed 001 eqs. 1-3): A ((1 + sin S)/2)^steepness, S = k (x·dir) - ω t.
struct SineWaveSpec {
  double amplitude_m = 0.6;
  double wavelength_m = 30;
  double direction_deg = 180;  // travels toward, compass degrees
  uint32_t steepness = 2;      // the exponent of eq. 2: 1 = a plain sine, higher = sharper crests
  double phase_deg = 0;        // added to S (not in eq. 1; sampled waves must not all crest at the origin)
};

struct SinesSet {
  SinesSet();  // out of line, as GerstnerSet
  std::vector<SineWaveSpec> waves;
  GerstnerDispersion dispersion = GerstnerDispersion::Deep;  // the phase speed ω/k of each wave
  // > 0: this many plain sines (steepness 1) sampled from `spectrum` as gerstner.spectrum_waves replace
  // waves.
  uint32_t spectrum_waves = 0;
};

// Perlin's gradient noise (seed 001 §1.1.1), octaves summed on the first cascade's patch (tileable).
struct PerlinParams {
  double amplitude_m = 0.6;  // of the first octave's noise (gradient noise peaks near ±0.7 of it)
  uint32_t cells = 16;       // lattice cells of the first octave across the first cascade's patch
  uint32_t octaves = 4;
  double persistence = 0.5;  // amplitude ratio between octaves
  uint32_t lacunarity = 2;   // frequency ratio between octaves (a whole number, so every octave tiles)
};

// Model springs (seed 001 §1.1.3, eqs. 4-5): a drop, a push on the water. It gives the nodes under a Gaussian
// of `radius_m` a downward velocity `speed_mps` at its centre, within the step that holds `time_s`.
struct SpringDrop {
  double x_m = 0, z_m = 0;
  double time_s = 0;
  double radius_m = 3;
  double speed_mps = 1;
};

// A wind gust: a downward pressure (force per node, N, at its centre) on a Gaussian patch of `radius_m` that
// starts at (x_m, z_m) and moves toward `direction_deg` at `speed_mps` from `time_s` for `duration_s`.
struct SpringGust {
  double x_m = 0, z_m = 0;
  double time_s = 0;
  double duration_s = 4;
  double radius_m = 6;
  double force_n = 2;
  double direction_deg = 180;  // compass degrees
  double speed_mps = 2;
};

struct SpringsParams {
  SpringsParams();  // out of line, as GerstnerSet
  // Table 1 of seed 001: node mass m, spring stiffness c, damping γ, step Δt (read as kg, N/m, kg/s, s).
  double mass_kg = 4.0;
  double stiffness_n_per_m = 7.0;
  double damping_kg_per_s = 0.05;
  double step_s = 0.4;
  // Eq. 4's rest length L as a fraction of the node spacing: 0 = linear springs (the ring speed is
  // sqrt(c/m) cells per second); toward 1 the springs are slack at rest and the waves nonlinear.
  double rest_length = 0.0;
  std::vector<SpringDrop> drops;
  std::vector<SpringGust> gusts;
  // The driven boundary: the nodes of the column x = 0 held at amplitude · sin(2π t / period); 0 = off.
  double boundary_amplitude_m = 0.0;
  double boundary_period_s = 8.0;
};

struct CascadeParams {
  double patch_size_m = 1000.0;  // side of the square tile this cascade repeats over
  uint32_t resolution = 256;     // N: samples per side, a power of two in [64, 1024]
};

// How much of the sea the whitecaps cover (ocean/whitecaps.h): as Monahan & O'Muircheartaigh (1980)
// observed for the wind, or where the Jacobian falls below foam.threshold (the seed's rule).
enum class FoamCoverage { Monahan, Threshold };

struct FoamParams {
  FoamCoverage coverage = FoamCoverage::Monahan;
  // Each cascade's foam builds where its Jacobian of the horizontal displacement J < threshold (J = 1 on
  // undisturbed water, < 1 where the surface is compressed, <= 0 where it folds over): new foam =
  // clamp(threshold - J, 0, 1), persisting as it decays. With coverage threshold the whole sea's Jacobian
  // whitens by the same rule; with monahan by ocean/whitecaps.h's.
  double threshold = 0.5;
  // Existing foam fades as (foam + 0.4) e^{-decay_per_s t} - 0.4 (shaders/shared/foam.h). 0.3: whitecaps'
  // foam at least ½ for 1.5 s at a point (field whitecaps: 0.5-8 s, Callaghan et al. 2012; validate's
  // foam.lifetime), gone within 4.2 s.
  double decay_per_s = 0.3;
};

struct OceanParams {
  uint32_t seed = 1;
  double depth_m = 1000.0;     // water depth for finite-depth dispersion and TMA; > 0
  double choppiness = 1.0;     // λ: horizontal displacement scale, 0 = none
  double loop_period_s = 0.0;  // > 0 quantises ω so every field repeats with this period; 0 = no loop
  SurfaceModel model = SurfaceModel::Fft;
  GerstnerSet gerstner;   // model gerstner: the waves (choppiness is every wave's steepness Q)
  SinesSet sines;         // model sines
  PerlinParams perlin;    // model perlin
  SpringsParams springs;  // model springs
  SpectrumParams spectrum;
  // Swell trains over the random sea (model fft and the other cascade models): Gerstner waves summed where
  // they are drawn, as model gerstner's, so that over the floor they shoal, turn and break (ocean/shoaling.h)
  // as the cascades' lattice waves cannot. Deep-water dispersion; a wave's steepness absent = choppiness.
  std::vector<GerstnerWaveSpec> swell_waves;
  std::vector<CascadeParams> cascades{{1000.0, 256}, {100.0, 256}, {10.0, 256}};
  FoamParams foam;
  // Waves that feel the floor (ocean/shoaling.h): `floor` is the scene's, set from its seafloor block by
  // world/floor_profile.h (none: the sea is depth_m deep everywhere); `shoaling` false leaves the waves as
  // they are over it; the breaker index γ is the height over depth at which they break.
  std::shared_ptr<const DepthProfile> floor;
  bool shoaling = true;
  double breaker_index = 0.78;
};

const char* to_string(
    SpectrumType type);  // "phillips", "pm", "jonswap", "tma", "jonswap-eq15", "phillips-eq18"
const char* to_string(Spreading spreading);     // "cos2", "cos2s", "donelan-banner"
const char* to_string(SurfaceModel model);      // "fft", "gerstner", "sines", "perlin", "springs"
const char* to_string(GerstnerDispersion law);  // "deep", "finite-depth", "capillary"
// Inverse of to_string; false when the name is unknown.
bool from_string(const std::string& name, SpectrumType& out);
bool from_string(const std::string& name, Spreading& out);
bool from_string(const std::string& name, SurfaceModel& out);
bool from_string(const std::string& name, GerstnerDispersion& out);

}  // namespace lagoon::ocean
