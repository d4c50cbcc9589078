#pragma once
/// How accurate the constitutive integration is against how long it takes:
/// the numbers behind the `integration_error` scene kind. Pure numerics.
///
/// 1. Drained triaxial compression (constant cell pressure, axial strain
///    driven) integrated with N increments; error of q and ε_v along the whole
///    path against a run with many more increments, and the wall time of a run.
/// 2. Iso-error maps: from a stress on the yield surface (plane, edge or apex),
///    one increment of size (x, y)·ε_y in two deviatoric directions, against the
///    same increment cut into many substeps.
#include <algorithm>
#include <array>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "drivers/point_integrator.hpp"

namespace ffp {

struct TriaxialErrorStudy {
  PointLaw law = LinearElastic(ElasticConstants{});
  double cell_pressure_Pa = 1.72e3;
  double axial_strain_max = 0.2;
  double strain_rate_per_s = 1e-4;
  std::vector<int> increments = {10, 20, 50, 100, 200, 500, 1000, 2000, 5000, 10000};
  int reference_increments = 100000;
  double min_timing_s = 0.05;  ///< repeat short runs until this much time is measured
};

struct TriaxialErrorRow {
  int increments = 0;
  double wall_time_s = 0.0;       ///< one run (mean over the repeats)
  double q_error = 0.0;           ///< at the end of the path: |q − q_ref| / peak q_ref
  double volumetric_error = 0.0;  ///< at the end of the path: |ε_v − ε_v,ref| / max |ε_v,ref|
  /// Over the whole path, the run's curve (linear between its increments) against
  /// the reference at every reference point: includes missing the peak between increments.
  double q_error_path = 0.0;
  double volumetric_error_path = 0.0;
  double peak_q_error = 0.0;  ///< |peak q − peak q_ref| / peak q_ref
  double peak_q_kPa = 0.0;
};

struct TriaxialErrorResult {
  std::vector<TriaxialErrorRow> rows;
  double reference_wall_time_s = 0.0;
  double reference_peak_q_kPa = 0.0;
  double reference_final_volumetric_strain = 0.0;
  long total_increments = 0;
};

/// The drained triaxial path with N increments (the scene's triaxial_compression path).
PointConfig drained_triaxial_config(const PointLaw& law, double cell_pressure_Pa, double axial_strain_max,
                                    double strain_rate_per_s, int increments);

TriaxialErrorResult run_triaxial_error_study(const TriaxialErrorStudy& study,
                                             const std::function<void(const std::string&)>& on_stage = {});

enum class MapStart { plane, edge, apex };
using MapStartName = std::pair<MapStart, std::string_view>;
/// The starts' names (output files iso_error_<law>_<start>.csv), in the order they run.
inline constexpr auto kMapStartNames =
    std::to_array<MapStartName>({{MapStart::plane, "plane"}, {MapStart::edge, "edge"}, {MapStart::apex, "apex"}});
inline std::string to_string(MapStart start) {
  return std::string(std::ranges::find(kMapStartNames, start, &MapStartName::first)->second);
}

struct IsoErrorMapStudy {
  PointLaw law = LinearElastic(ElasticConstants{});
  MapStart start = MapStart::plane;
  double confining_Pa = 1.72e3;  ///< σ3 of the plane and edge starting states
  int points_x = 21;             ///< x in [0, max]: along triaxial-compression deviatoric strain
  int points_y = 41;             ///< y in [−max, max]: along the orthogonal (Lode) deviatoric strain
  double max_multiple = 10.0;    ///< largest increment in yield strains ε_y
  int reference_substeps = 2000;
};

/// Errors on a grid: error[iy * x.size() + ix], relative to the size of the
/// starting stress on the plane, |σ_plane|_F (the same scale for all three starts).
struct IsoErrorMap {
  std::vector<double> x, y;
  std::vector<double> error;
  double yield_strain = 0.0;  ///< ε_y = q_y / 3G, q_y the edge start's q
  Voigt start_stress = Voigt::Zero();
  long updates = 0;
};

IsoErrorMap run_iso_error_map(const IsoErrorMapStudy& study);

}  // namespace ffp
