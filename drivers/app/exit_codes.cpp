#include "drivers/app/exit_codes.hpp"

#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>
#include <string>

#include "drivers/app/job.hpp"
#include "drivers/output/interrupt.hpp"
#include "drivers/output/machine_memory.hpp"
#include "drivers/output/run_directory.hpp"
#include "drivers/scene/scene_error.hpp"

namespace ffp {

namespace {

int say(const char* what, int code) {
  std::fprintf(stderr, "error: %s\n", what);
  return code;
}

int interrupted(std::string_view note) {
  if (note.empty())
    std::fputs("interrupted\n", stderr);
  else
    std::fprintf(stderr, "interrupted: %.*s\n", static_cast<int>(note.size()), note.data());
  return kExitInterrupted;
}

/// " (this process may use 102 MB: ulimit -v)": std::bad_alloc says nothing of the limit it met.
/// The stack has unwound by now, freeing what was being built, so this text can be made.
std::string memory_allowed() {
  const MemoryLimit limit = usable_memory();
  if (!std::isfinite(limit.bytes)) return "";
  return " (this process may use " + format_bytes(limit.bytes) + ": " + limit.source + ")";
}

/// A numerical failure; with a reproducer, the scene that repeats the failing step beside it.
int run_failed(const RunFailure& e) {
  if (!e.reproducer().is_object()) return say(e.what(), kExitRunFailed);
  const std::filesystem::path file = "failed-step.json";
  try {
    write_file_atomically(file, e.reproducer().dump(2) + "\n");
  } catch (const std::exception& not_written) {
    std::fprintf(stderr, "error: %s\n  (the scene that repeats the failing step could not be written: %s)\n", e.what(),
                 not_written.what());
    return kExitRunFailed;
  }
  std::fprintf(stderr, "error: %s\n  a scene that repeats the failing step: %s\n", e.what(), file.string().c_str());
  return kExitRunFailed;
}

}  // namespace

int exit_code_of_current_exception(std::string_view interrupted_note) {
  try {
    throw;
  } catch (const SceneError& e) {
    return say(e.what(), kExitBadInput);
  } catch (const Interrupted&) {
    return interrupted(interrupted_note);
  } catch (const std::bad_alloc&) {
    return say(("out of memory" + memory_allowed() +
                ": the model or its output did not fit; use a coarser mesh or fewer particles per cell "
                "(ffp check SCENE prints the model's size), a longer output.history_interval_s, a shorter record "
                "or table, or fewer runs at once (--jobs)")
                   .c_str(),
               kExitRunFailed);
  } catch (const std::exception& e) {
    // A Ctrl-C reaches the whole process group: a model run it stopped, or a write it cut
    // short, can surface here as a failure. The user asked the command to stop, and it did.
    if (interrupt_requested()) return interrupted(interrupted_note);
    if (const auto* failure = dynamic_cast<const RunFailure*>(&e)) return run_failed(*failure);
    return say(e.what(), kExitRunFailed);
  } catch (...) {
    return say("an error that names no cause (not a std::exception)", kExitRunFailed);
  }
}

int exit_code_after_command(int code) {
  if (code == kExitInterrupted || code == kExitBadInput || !interrupt_requested()) return code;
  return interrupted({});
}

}  // namespace ffp
