#pragma once
/// A nearly full disk for real: a tmpfs of a few pages mounted on a folder, and
/// unmounted when this goes out of scope (a failed REQUIRE included). Mounting
/// needs root with CAP_SYS_ADMIN; where the machine forbids it, mounted() is
/// false and why_not() says why (the test then WARNs and returns).
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>

#include <sys/mount.h>

namespace ffp::test_support {

class SmallTmpfs {
 public:
  SmallTmpfs(std::filesystem::path folder, const std::string& size) : folder_(std::move(folder)) {
    std::filesystem::create_directories(folder_);
    mounted_ = ::mount("tmpfs", folder_.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, ("size=" + size).c_str()) == 0;
    if (!mounted_) why_not_ = "cannot mount a tmpfs on " + folder_.string() + ": " + std::strerror(errno);
  }
  ~SmallTmpfs() {
    if (mounted_) ::umount2(folder_.c_str(), MNT_DETACH);
  }
  SmallTmpfs(const SmallTmpfs&) = delete;
  SmallTmpfs& operator=(const SmallTmpfs&) = delete;
  bool mounted() const { return mounted_; }
  const std::string& why_not() const { return why_not_; }
  const std::filesystem::path& path() const { return folder_; }

 private:
  std::filesystem::path folder_;
  bool mounted_ = false;
  std::string why_not_;
};

}  // namespace ffp::test_support
