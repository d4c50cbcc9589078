#include "drivers/output/run_directory.hpp"

#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include <unistd.h>

#include "drivers/output/interrupt.hpp"

namespace ffp {

namespace fs = std::filesystem;

namespace {
fs::path sibling(const fs::path& target, const std::string& tag) {
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::string name = ".";  // built step by step: GCC 12 warns falsely (-Wrestrict) on "." + string
  name += target.filename().string();
  name += '.';
  name += tag;
  name += '-';
  name += std::to_string(::getpid());
  return parent / name;
}
}  // namespace

RunDirectory::RunDirectory(fs::path target) : target_(std::move(target)) {
  if (target_.filename().empty()) target_ = target_.parent_path();
  if (target_.has_parent_path()) fs::create_directories(target_.parent_path());
  working_ = sibling(target_, "tmp");
  fs::remove_all(working_);
  fs::create_directories(working_);
  register_cleanup_path(working_);
}

RunDirectory::~RunDirectory() {
  if (!committed_) {
    std::error_code ignored;
    fs::remove_all(working_, ignored);
  }
  unregister_cleanup_path(working_);
}

void RunDirectory::commit() {
  const fs::path old = sibling(target_, "old");
  std::error_code ec;
  fs::remove_all(old, ec);
  const bool had_previous = fs::exists(target_);
  if (had_previous) fs::rename(target_, old);
  fs::rename(working_, target_);
  committed_ = true;
  if (had_previous) fs::remove_all(old, ec);
}

void write_file_atomically(const fs::path& file, const std::string& content) {
  const fs::path temporary = file.string() + ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary);
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
    out << content;
    if (!out) throw std::runtime_error("error writing " + temporary.string());
  }
  fs::rename(temporary, file);
}

}  // namespace ffp
