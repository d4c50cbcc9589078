#pragma once
/// The program's version: the project version and `git describe` of the source
/// tree at the last build (e.g. "0.1.0 (c0d3a81-dirty)"), or "unknown" outside git.
/// It goes into every run's summary.json (`ffp_version`) and into the run cache's
/// key, so it is taken at build time, not when CMake configured the build.
namespace ffp {

const char* program_version();

}  // namespace ffp
