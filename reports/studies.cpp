/// The list of studies in the validation report, in reading order.
#include "reports/studies/studies.hpp"
#include "reports/study.hpp"

namespace ffp {

std::vector<Study> validation_studies(const std::filesystem::path& scenes_dir) {
  std::vector<Study> studies;
  studies.push_back(calibration_study(scenes_dir));
  studies.push_back(mesh_calibration_study(scenes_dir));
  studies.push_back(integration_error_study(scenes_dir));
  studies.push_back(punch_bearing_study(scenes_dir));  // verification before the comparison with the paper
  studies.push_back(saturated_verification_study(scenes_dir));
  studies.push_back(saturated_drop_study(scenes_dir));  // outside the main job
  studies.push_back(ffp_paper_comparison_study(scenes_dir));
  studies.push_back(ffp_localisation_study(scenes_dir));
  studies.push_back(ffp_sands_side_by_side_study(scenes_dir));
  studies.push_back(ffp_chamber_study(scenes_dir));
  studies.push_back(ffp_compressibility_study(scenes_dir));
  studies.push_back(ffp_stiffness_study(scenes_dir));
  studies.push_back(ffp_contact_friction_study(scenes_dir));
  studies.push_back(ffp_dilatancy_study(scenes_dir));
  studies.push_back(ffp_peak_friction_study(scenes_dir));
  studies.push_back(ffp_rate_factor_study(scenes_dir));
  studies.push_back(ffp_convergence_study(scenes_dir));
  studies.push_back(ffp_softening_convergence_study(scenes_dir));
  studies.push_back(inverse_study(scenes_dir));
  return studies;
}

}  // namespace ffp
