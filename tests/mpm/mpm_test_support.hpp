#pragma once
/// Small builders shared by the MPM verification tests.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "mpm/model.hpp"

namespace ffp::mpm::testing {

/// n equal cells from a to b (n + 1 nodes).
inline std::vector<double> nodes(double a, double b, int cells) {
  std::vector<double> x;
  for (int i = 0; i <= cells; ++i) x.push_back(a + (b - a) * i / cells);
  return x;
}

inline BodyDescription elastic_body(std::string name, double E_Pa, double nu, double density, Region region,
                                    double vr = 0.0, double vz = 0.0, int ppc = 2,
                                    std::optional<GeostaticStress> k0 = std::nullopt) {
  return BodyDescription{
      std::move(name), LinearElastic(ElasticConstants{E_Pa, nu}), density, region, ppc, ppc, vr, vz, k0};
}

}  // namespace ffp::mpm::testing
