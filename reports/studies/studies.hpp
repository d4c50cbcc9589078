#pragma once
/// One function per study of the validation report.
#include <filesystem>

#include "reports/study.hpp"

namespace ffp {

Study integration_error_study(const std::filesystem::path& scenes_dir);
Study calibration_study(const std::filesystem::path& scenes_dir);

}  // namespace ffp
