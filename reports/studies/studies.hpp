#pragma once
/// One function per study of the validation report.
#include <filesystem>

#include "reports/study.hpp"

namespace ffp {

Study integration_error_study(const std::filesystem::path& scenes_dir);
Study calibration_study(const std::filesystem::path& scenes_dir);
Study mesh_calibration_study(const std::filesystem::path& scenes_dir);
Study ffp_compressibility_study(const std::filesystem::path& scenes_dir);
Study ffp_stiffness_study(const std::filesystem::path& scenes_dir);
Study ffp_contact_friction_study(const std::filesystem::path& scenes_dir);
Study ffp_dilatancy_study(const std::filesystem::path& scenes_dir);
Study ffp_peak_friction_study(const std::filesystem::path& scenes_dir);
Study ffp_rate_factor_study(const std::filesystem::path& scenes_dir);
Study ffp_convergence_study(const std::filesystem::path& scenes_dir);
Study ffp_softening_convergence_study(const std::filesystem::path& scenes_dir);
Study ffp_paper_comparison_study(const std::filesystem::path& scenes_dir);
Study ffp_localisation_study(const std::filesystem::path& scenes_dir);
Study ffp_sands_side_by_side_study(const std::filesystem::path& scenes_dir);
Study ffp_chamber_study(const std::filesystem::path& scenes_dir);
Study punch_bearing_study(const std::filesystem::path& scenes_dir);
Study saturated_verification_study(const std::filesystem::path& scenes_dir);
Study saturated_drop_study(const std::filesystem::path& scenes_dir);
Study inverse_study(const std::filesystem::path& scenes_dir);

}  // namespace ffp
