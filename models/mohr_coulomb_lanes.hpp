#pragma once
/// The Mohr–Coulomb return of four planar trials at once, in vector lanes: what
/// MohrCoulomb::return_from_trial does to a point whose θθ is principal (the
/// axisymmetric MPM), lane by lane the same operations in the same order, so the
/// same bits (tests/models/mohr_coulomb_test.cpp). Every region (plane, both edges,
/// apex) is formed in every lane and the scalar return's choice is taken by masks:
/// the scalar return's chain of up to five divisions and its branches on a
/// mixed stream of regions cost more than the four lanes' whole work.
#include <cstddef>

#include "models/mohr_coulomb_return.hpp"
#include "models/voigt.hpp"

namespace ffp {

/// Returns stress[point[k]], k < 4, each an elastic trial with zero 23 and 13 shears,
/// onto the surface of `strength` (sin φ > 0: Tresca's corner case stays scalar);
/// `directions` are ReturnDirections::of(strength, the stiffness). A trial inside the
/// surface is left as it is.
void return_planar_trials(Voigt* stress, const std::size_t point[4], const MohrCoulombStrength& strength,
                          const ReturnDirections& directions);

}  // namespace ffp
