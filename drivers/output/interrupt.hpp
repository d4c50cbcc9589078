#pragma once
/// Ctrl-C and SIGTERM: the handler only sets a flag; long loops poll it through
/// throw_if_interrupted(), and unwinding removes temporary output.
#include <filesystem>
#include <stdexcept>

namespace ffp {

class Interrupted : public std::runtime_error {
 public:
  Interrupted() : std::runtime_error("interrupted") {}
};

void install_interrupt_handlers();
bool interrupt_requested();
void throw_if_interrupted();

/// Temporary paths removed at exit if unwinding did not reach them.
void register_cleanup_path(const std::filesystem::path& path);
void unregister_cleanup_path(const std::filesystem::path& path);

}  // namespace ffp
