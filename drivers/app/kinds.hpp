#pragma once
/// Factories of the scene kinds, one file each.
#include "drivers/app/job.hpp"

namespace ffp {

std::unique_ptr<Job> make_point_job(SceneReader& scene, const std::filesystem::path& scene_dir);
std::unique_ptr<Job> make_mpm_job(SceneReader& scene, const std::filesystem::path& scene_dir);
std::unique_ptr<Job> make_integration_error_job(SceneReader& scene, const std::filesystem::path& scene_dir);
std::unique_ptr<Job> make_triaxial_job(SceneReader& scene, const std::filesystem::path& scene_dir);
std::unique_ptr<Job> make_calibration_job(SceneReader& scene, const std::filesystem::path& scene_dir);
std::unique_ptr<Job> make_ffp_job(SceneReader& scene, const std::filesystem::path& scene_dir);
std::unique_ptr<Job> make_cpt_job(SceneReader& scene, const std::filesystem::path& scene_dir);
std::unique_ptr<Job> make_record_job(SceneReader& scene, const std::filesystem::path& scene_dir);
std::unique_ptr<Job> make_inverse_job(SceneReader& scene, const std::filesystem::path& scene_dir);

}  // namespace ffp
