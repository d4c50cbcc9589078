#pragma once
/// What the fuzz targets share: which exceptions are the readers' contract for
/// bad input, and a scratch file for the readers that take a path.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "drivers/scene/scene_error.hpp"

namespace ffp::fuzz {

/// Runs `read`, letting through only the rejections bad input may end in:
/// SceneError, std::invalid_argument and nlohmann::json's exceptions. Any other
/// exception escapes, std::terminate aborts, and libFuzzer records the input.
template <class Read>
void expect_only_rejections(Read&& read) {
  try {
    read();
  } catch (const SceneError&) {
  } catch (const std::invalid_argument&) {
  } catch (const nlohmann::json::exception&) {
  }
}

/// `<tmp>/ffp-fuzz-<pid>-<name>`: one per process, so parallel runs never share
/// a file. Hold it in a static: it is removed when the process exits normally.
struct ScratchFile {
  explicit ScratchFile(const std::string& name)
      : path(std::filesystem::temp_directory_path() / ("ffp-fuzz-" + std::to_string(::getpid()) + "-" + name)) {}
  ~ScratchFile() {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
  }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;

  /// Replaces the file's content by the fuzz input.
  void write(const std::uint8_t* data, std::size_t size) const {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out.flush()) {
      std::perror(path.c_str());
      std::abort();
    }
  }

  std::filesystem::path path;
};

}  // namespace ffp::fuzz
