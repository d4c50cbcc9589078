#include "mpm/signal_maxima.hpp"

#include <cmath>
#include <limits>

#include "models/voigt_lanes.hpp"

namespace ffp::mpm {

// Four particles per vector (models/voigt_lanes.hpp), the last ones one by one.
SignalMaxima signal_maxima(const Particles& p, std::size_t begin, std::size_t end) {
  constexpr double kLargest = std::numeric_limits<double>::max();
  SignalMaxima m;
  std::size_t i = begin;
  if (end - begin >= 4) {
    Lanes stiffest{}, speed2{}, stress{};
    LaneMask bad{};
    for (; i + 4 <= end; i += 4) {
      const Lanes inverse_density = load_lanes(&p.volume[i]) / load_lanes(&p.mass[i]);
      const Lanes vr = load_lanes(&p.vr[i]), vz = load_lanes(&p.vz[i]);
      const Lanes v2 = vr * vr + vz * vz;
      Lanes sig[6];
      to_lanes(p.stress[i].data(), sig);
      const Lanes shear = abs_lanes(sig[3]);
      const Lanes bound = max_lanes(max_lanes(abs_lanes(sig[0]) + shear, abs_lanes(sig[1]) + shear), abs_lanes(sig[2]));
      bad -= ~(inverse_density > 0.0) | ~(abs_lanes(inverse_density) <= kLargest) | ~(abs_lanes(v2) <= kLargest) |
             ~(abs_lanes(bound) <= kLargest);  // a true lane is −1
      stiffest = max_lanes(stiffest, inverse_density);
      speed2 = max_lanes(speed2, v2);
      stress = max_lanes(stress, bound);
    }
    for (int k = 0; k < 4; ++k) {
      m.stiffest = std::max(m.stiffest, stiffest[k]);
      m.speed2 = std::max(m.speed2, speed2[k]);
      m.stress = std::max(m.stress, stress[k]);
      m.bad += bad[k];
    }
  }
  for (; i < end; ++i) {
    const double inverse_density = p.volume[i] / p.mass[i];
    const double v2 = p.vr[i] * p.vr[i] + p.vz[i] * p.vz[i];
    const Voigt& sig = p.stress[i];
    const double bound =
        std::max({std::abs(sig[0]) + std::abs(sig[3]), std::abs(sig[1]) + std::abs(sig[3]), std::abs(sig[2])});
    if (!(inverse_density > 0.0) || !std::isfinite(inverse_density) || !std::isfinite(v2) || !std::isfinite(bound))
      ++m.bad;
    m.stiffest = std::max(m.stiffest, inverse_density);
    m.speed2 = std::max(m.speed2, v2);
    m.stress = std::max(m.stress, bound);
  }
  return m;
}

}  // namespace ffp::mpm
