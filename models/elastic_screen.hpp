#pragma once
/// The elastic screen of a Mohr–Coulomb batch update in vector lanes: for a block
/// of points, each point's elastic trial σ + λ tr(Δε) I + 2G Δε in place of its
/// stress, and whether the point settles there (θθ principal and f ≤ 0 at the
/// trial). Most points of an MPM step settle; the others return from the trial.
/// The same operations as ElasticTrial, so the same bits
/// (tests/models/mohr_coulomb_test.cpp).
#include <cstddef>

#include "models/elastic.hpp"
#include "models/mohr_coulomb_return.hpp"
#include "models/voigt.hpp"

namespace ffp {

/// stress[i] ← its elastic trial and settled[i] ← (trial planar and f(trial) ≤ 0), i < n.
void screen_elastic_trials(Voigt* stress, const Voigt* strain_increment, std::size_t n, const ElasticStiffness& d,
                           const MohrCoulombStrength& strength, bool* settled);

}  // namespace ffp
