#pragma once
/// One function per study of the validation report.
#include <filesystem>

#include "reports/study.hpp"

namespace ffp {

}  // namespace ffp
