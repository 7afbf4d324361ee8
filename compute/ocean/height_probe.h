// The height of the displaced sea surface above one point, cheaply enough to ask every frame: is the camera
// above the water or under it (world/camera_medium.h)? WaveQuery answers this and more for any number of
// points, but first evaluates every field with an FFT per new time (15-30 ms for 3 x 256² on 2 cores). One
// point needs only the modes that matter: the probe sums Re Σ F(k)e^{ik·x} directly over the modes of the
// largest amplitude a(k) = |h0(k)| + |h0(-k)| and leaves out the smallest ones. |h̃(k,t)| never exceeds
// a(k), so the modes left out change the height and each displacement component by at most the sum of
// their amplitudes: a rigorous bound, fixed when the probe is made.
#pragma once
#include <complex>
#include <glm/vec2.hpp>
#include <vector>

#include "ocean/initial_spectrum.h"
#include "ocean/ocean_params.h"
#include "ocean/shoaling.h"

namespace lagoon::ocean {

class HeightProbe {
 public:
  struct Answer {
    double height = 0;         // m above the mean level, of the surface point displaced to (x, z)
    double error_bound_m = 0;  // against the full band-limited sum the GPU draws
    bool converged = true;     // false where the displacement inversion did not converge (folded crests)
  };

  // Keeps the largest modes until those left out bound the height's error by `tolerance_m`.
  HeightProbe(const OceanParams& params, const std::vector<CascadeSpectrum>& spectra, double tolerance_m);

  // Over `floor` (the random sea's table, ocean/shoaling.h) each cascade is read where its lattice has
  // moved; the height is not scaled by the depth (the caller's).
  Answer height(double time_s, double x, double z, const Shoaling* floor = nullptr) const;
  size_t modes() const { return modes_.size(); }

 private:
  struct Mode {
    double kx, kz, inv_k, omega;
    std::complex<double> h0, h0_mirrored_conj;  // h0(k) and conj(h0(-k))
    uint32_t phase_x, phase_z;                  // rows of e^{ik·p}'s two factors in the phase tables
  };
  struct Axis {  // one cascade's wavenumbers along x or z: dk·m for m = -N/2 .. N/2 - 1
    double dk;
    uint32_t n, first_row;
  };
  // e^{i·dk·m·p} for every cascade and m, along x and then z: 2·ΣN sine-cosine pairs per point instead
  // of one per mode.
  // Each cascade at its own point (its lattice's move over the floor).
  void phase_tables(const Shoaling::LatticeMoves& p, std::vector<std::complex<double>>& table) const;
  std::vector<Mode> modes_;
  std::vector<Axis> axes_;
  uint32_t table_rows_ = 0;
  double choppiness_;
  double bound_m_ = 0;
};

}  // namespace lagoon::ocean
