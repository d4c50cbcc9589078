#pragma once
/// Any of the project's constitutive laws, and the parameter set of each: the
/// one variant the point driver, the triaxial test and the MPM all take, so a
/// scene's material is turned into a law in one place.
#include <variant>

#include "models/elastic.hpp"
#include "models/mohr_coulomb.hpp"
#include "models/strain_softening_mohr_coulomb.hpp"

namespace ffp {

using MaterialLaw = std::variant<LinearElastic, MohrCoulomb, StrainSofteningMohrCoulomb>;
using MaterialParameters = std::variant<ElasticConstants, MohrCoulombParameters, StrainSofteningParameters>;

/// The law with these parameters (same alternative index).
MaterialLaw make_law(const MaterialParameters& parameters);

/// K0 at rest when none is given: Jaky (1944) 1 − sin φ'_p for the frictional
/// laws (1 − sin 38° = 0.384; the paper's Table 1 rounds to 0.39), ν/(1 − ν) (lateral confinement) for an elastic one.
double at_rest_k0(const MaterialParameters& parameters);

}  // namespace ffp
