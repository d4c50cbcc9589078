#include "drivers/output/run_directory.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "drivers/output/interrupt.hpp"

namespace ffp {

namespace fs = std::filesystem;

namespace {

std::string hidden_prefix(const fs::path& target, const std::string& tag) {
  std::string name = ".";  // built step by step: GCC 12 warns falsely (-Wrestrict) on "." + string
  name += target.filename().string();
  name += '.';
  name += tag;
  name += '-';
  return name;
}

fs::path sibling(const fs::path& target, const std::string& tag) {
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  return parent / (hidden_prefix(target, tag) + std::to_string(::getpid()));
}

bool process_alive(long pid) { return pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH); }

/// Every entry under `folder`, relative, sorted (the manifest itself left out).
std::vector<std::string> entries_under(const fs::path& folder) {
  std::vector<std::string> entries;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(folder, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    const std::string relative = fs::relative(it->path(), folder).generic_string();
    if (relative != kOutputManifest) entries.push_back(relative);
  }
  std::sort(entries.begin(), entries.end());
  return entries;
}

/// `file` opened for reading, or a closed stream when it is not a regular file: a named pipe in a
/// folder the user named would otherwise keep the check waiting for a writer.
std::ifstream open_if_regular(const fs::path& file) {
  std::error_code ec;
  return fs::is_regular_file(file, ec) ? std::ifstream(file) : std::ifstream();
}

/// The entries a folder's manifest lists; nullopt-like empty set plus false when it has none (or it is unreadable).
bool read_manifest(const fs::path& folder, std::set<std::string>& listed) {
  std::ifstream in = open_if_regular(folder / kOutputManifest);
  if (!in) return false;
  const nlohmann::json manifest = nlohmann::json::parse(in, nullptr, false);
  if (!manifest.is_object() || !manifest.contains("files") || !manifest["files"].is_array()) return false;
  for (const auto& f : manifest["files"])
    if (f.is_string()) listed.insert(f.get<std::string>());
  return true;
}

std::string describe_foreign(const std::vector<std::string>& foreign) {
  std::string text = "'" + foreign.front() + "'";
  if (foreign.size() > 1) text += " and " + std::to_string(foreign.size() - 1) + " more";
  return text;
}

/// The process id of `name` if it is "<base>.tmp-<pid>" (write_file_atomically's temporary), else 0.
long temporary_owner(const std::string& name, const std::string& base) {
  const std::string prefix = base + ".tmp-";
  if (!name.starts_with(prefix) || name.size() == prefix.size() || name.size() > prefix.size() + 9) return 0;
  const std::string digits = name.substr(prefix.size());
  if (!std::all_of(digits.begin(), digits.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
    return 0;
  return std::stol(digits);
}

/// "<label>-<16 hex>" (a run folder of the run cache), ".<label>.log", a run's ".<folder>.lock" (left
/// by a run killed with SIGKILL; an OutputLock), or the folder's own manifest being written
/// (".ffp-output.json.tmp-<pid>": an ffp killed in that instant leaves it behind).
bool looks_like_cache_entry(const fs::directory_entry& entry) {
  const std::string name = entry.path().filename().string();
  if (entry.is_regular_file())
    return (name.size() > 5 && name.front() == '.' && (name.ends_with(".log") || name.ends_with(".lock"))) ||
           temporary_owner(name, kOutputManifest) > 0;
  if (!entry.is_directory()) return false;
  if (name.front() == '.') return name.find(".tmp-") != std::string::npos || name.find(".old-") != std::string::npos;
  if (name.size() < 18 || name[name.size() - 17] != '-') return false;
  return std::all_of(name.end() - 16, name.end(), [](char c) { return std::isxdigit(static_cast<unsigned char>(c)); });
}

/// A run or report folder written before manifests existed: its summary.json
/// names the ffp version, or its report.md is the validation report.
bool written_before_manifests(const fs::path& folder) {
  std::ifstream summary = open_if_regular(folder / "summary.json");
  if (summary) {
    const nlohmann::json s = nlohmann::json::parse(summary, nullptr, false);
    return s.is_object() && s.contains("ffp_version");
  }
  std::ifstream report = open_if_regular(folder / "report.md");
  std::string first_line;
  return report && std::getline(report, first_line) && first_line == "# ffp validation report";
}

/// `path` without trailing separators ("out/" names the folder "out").
fs::path folder_path(fs::path path) {
  while (path.filename().empty() && path.has_parent_path() && path.parent_path() != path) path = path.parent_path();
  return path;
}

/// What a path that exists but is no folder is, for messages.
std::string kind_of(const fs::file_status& status) {
  switch (status.type()) {
    case fs::file_type::regular:
      return "a file";
    case fs::file_type::fifo:
      return "a named pipe";
    case fs::file_type::character:
    case fs::file_type::block:
      return "a device";
    case fs::file_type::socket:
      return "a socket";
    default:
      return "not a folder";
  }
}

/// ffp never replaces a symbolic link (nor writes through one): what the user named
/// on the command line would then not be what changed. "latest -> run_old" is
/// usually a pointer meant to stay as it is, and replacing its target would
/// overwrite a run the user did not name. Nor anything but a folder, --force or
/// not: a file the user named by mistake is theirs.
void require_folder_or_nothing(const fs::path& folder, const std::string& option, bool force) {
  const std::string name = folder.filename().string();
  if (name.empty() || name == "." || name == "..")
    throw OutputFolderRefused(option + ": '" + folder.string() +
                              "' is not a folder ffp can replace: name one inside it (e.g. " + option +
                              " results/run1)");
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(folder, ec);
  if (fs::is_symlink(status)) {
    const fs::path target = fs::read_symlink(folder, ec);
    throw OutputFolderRefused(option + ": '" + folder.string() + "' is a symbolic link (to '" + target.string() +
                              "'); ffp does not replace links: name the folder itself, or another one");
  }
  if (fs::exists(status) && !fs::is_directory(status))
    throw OutputFolderRefused(option + ": '" + folder.string() + "' is " + kind_of(status) + ", not a folder" +
                              (force ? " (--force replaces only folders)" : "") + ": choose another name");
}

/// The name must leave room for ffp's hidden siblings: ".NAME.tmp-PID" (13 bytes more than NAME with a
/// 7-digit process id, Linux's largest) must fit the file system's limit on one name.
void require_short_name(const fs::path& target, const std::string& option) {
  fs::path existing = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  while (!fs::exists(existing, ec) && existing.has_parent_path() && existing.parent_path() != existing)
    existing = existing.parent_path();
  const long limit = ::pathconf(existing.c_str(), _PC_NAME_MAX);
  const std::size_t name_max = limit > 0 ? static_cast<std::size_t>(limit) : 255;
  constexpr std::size_t kSiblingExtra = 13;
  const std::string name = target.filename().string();
  if (name.size() + kSiblingExtra <= name_max) return;
  throw OutputFolderRefused(option + ": the name '" + name.substr(0, 24) + "…' is " + std::to_string(name.size()) +
                            " bytes long; at most " + std::to_string(name_max - kSiblingExtra) +
                            " fit here (this file system allows " + std::to_string(name_max) +
                            " per name, and ffp writes '.NAME.tmp-PID' beside it while it runs)");
}

/// Creates `folder` (and its parents), or throws OutputFolderRefused naming `option`, the place
/// and the system's reason: a read-only or foreign place is the user's choice, so bad input.
void create_folder(const fs::path& folder, const std::string& option) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (!ec) return;
  throw OutputFolderRefused(option + ": cannot create '" + folder.string() + "': " + ec.message());
}

}  // namespace

std::vector<std::string> files_not_written_by_ffp(const fs::path& folder) {
  std::error_code ec;
  if (!fs::exists(folder, ec)) return {};
  if (!fs::is_directory(folder, ec)) return {folder.filename().string()};
  std::set<std::string> listed;
  std::vector<std::string> foreign;
  if (!read_manifest(folder, listed) && written_before_manifests(folder)) {
    // No list of its files: only the top-level names ffp writes pass.
    static const std::set<std::string> ffp_names = {"summary.json", "history.csv", "plots",  "fields",
                                                    "report.md",    "figures",     "tables", "failed-step.json"};
    for (const auto& entry : fs::directory_iterator(folder, ec))
      if (!ffp_names.contains(entry.path().filename().string())) foreign.push_back(entry.path().filename().string());
    std::sort(foreign.begin(), foreign.end());
    return foreign;
  }
  for (const auto& entry : entries_under(folder))
    if (!listed.contains(entry)) foreign.push_back(entry);
  return foreign;
}

void require_replaceable(const fs::path& given, const std::string& option, bool force) {
  const fs::path folder = folder_path(given);
  require_folder_or_nothing(folder, option, force);
  if (force) return;
  const auto foreign = files_not_written_by_ffp(folder);
  if (foreign.empty()) return;
  throw OutputFolderRefused(option + ": '" + folder.string() + "' holds " + describe_foreign(foreign) +
                            ", which ffp did not write: choose another folder, or pass --force to replace it");
}

void write_manifest(const fs::path& folder, const std::string& what) {
  nlohmann::json manifest = {{"written_by", "ffp"}, {"what", what}, {"files", entries_under(folder)}};
  write_file_atomically(folder / kOutputManifest, manifest.dump(1) + "\n", Durability::synced);
}

void claim_persistent_folder(const fs::path& folder, const std::string& option, const std::string& what, bool force) {
  std::error_code ec;
  // A link to a folder is followed: this folder is added to, never replaced, and a cache on
  // another disk reached through a link is a common set-up. A link to nothing is refused.
  if (fs::is_symlink(fs::symlink_status(folder, ec)) && !fs::exists(folder, ec))
    throw OutputFolderRefused(option + ": '" + folder.string() + "' is a symbolic link to nothing (to '" +
                              fs::read_symlink(folder, ec).string() + "'): create its target, or name another folder");
  if (fs::exists(folder, ec) && !fs::is_directory(folder, ec))
    throw OutputFolderRefused(option + ": '" + folder.string() + "' is " + kind_of(fs::status(folder, ec)) +
                              ", not a folder: choose another name");
  // A temporary of the folder's own files (its manifest, a sweep's table) whose writer is dead (killed
  // between writing and renaming it) is ffp's leftover: removed, so that it neither stays nor makes the
  // folder look foreign.
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    const long owner = std::max(temporary_owner(name, kOutputManifest), temporary_owner(name, kSweepTable));
    std::error_code ignored;
    if (owner > 0 && !process_alive(owner)) fs::remove(entry.path(), ignored);
  }
  if (fs::exists(folder / kOutputManifest, ec)) return;
  bool ours = true;
  std::vector<std::string> foreign;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    if (!looks_like_cache_entry(entry)) {
      ours = false;
      foreign.push_back(entry.path().filename().string());
    }
  }
  if (!ours && !force)
    throw OutputFolderRefused(option + ": '" + folder.string() + "' holds " + describe_foreign(foreign) +
                              ", which ffp did not write: choose another folder, or pass --force to use it");
  create_folder(folder, option);
  // A persistent folder's manifest only marks it as ffp's; its runs carry their own.
  nlohmann::json manifest = {{"written_by", "ffp"}, {"what", what}, {"files", nlohmann::json::array()}};
  write_file_atomically(folder / kOutputManifest, manifest.dump(1) + "\n", Durability::synced);
}

void remove_stale_siblings(const fs::path& target) {
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(parent, ec)) {
    const std::string name = entry.path().filename().string();
    for (const char* tag : {"tmp", "old"}) {
      const std::string prefix = hidden_prefix(target, tag);
      if (!name.starts_with(prefix) || name.size() == prefix.size()) continue;
      const std::string digits = name.substr(prefix.size());
      if (!std::all_of(digits.begin(), digits.end(),
                       [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
        continue;
      if (digits.size() > 9 || process_alive(std::stol(digits))) continue;
      std::error_code ignored;
      fs::remove_all(entry.path(), ignored);
    }
  }
}

RunDirectory::RunDirectory(fs::path target, std::string option, bool force)
    : target_(folder_path(std::move(target))), option_(std::move(option)), force_(force) {
  require_replaceable(target_, option_, force_);
  require_short_name(target_, option_);
  if (target_.has_parent_path()) create_folder(target_.parent_path(), option_);
  remove_stale_siblings(target_);
  working_ = sibling(target_, "tmp");
  std::error_code error;
  fs::remove_all(working_, error);
  fs::create_directory(working_, error);
  if (error)
    throw OutputFolderRefused(option_ + ": cannot write in '" + working_.parent_path().string() +
                              "' (making its temporary folder " + working_.filename().string() + ": " +
                              error.message() + ")");
  register_cleanup_path(working_);
  // The lock is held only while the temporary folder exists (taken after it is made, let go before
  // it is removed): whoever sees a killed run's temporary folders gone finds the target free.
  try {
    lock_ = std::make_unique<OutputLock>(target_, option_);
  } catch (...) {
    fs::remove_all(working_, error);
    unregister_cleanup_path(working_);
    throw;
  }
}

RunDirectory::~RunDirectory() {
  lock_.reset();
  if (!committed_) {
    std::error_code ignored;
    fs::remove_all(working_, ignored);
  }
  unregister_cleanup_path(working_);
}

void RunDirectory::commit(const std::string& what) {
  write_manifest(working_, what);
  require_replaceable(target_, option_, force_);  // the user may have put a file there meanwhile
  const fs::path old = sibling(target_, "old");
  std::error_code ec;
  fs::remove_all(old, ec);
  const bool had_previous = fs::exists(target_);
  try {
    if (had_previous) fs::rename(target_, old);
    fs::rename(working_, target_);
  } catch (const fs::filesystem_error& e) {
    if (had_previous && !fs::exists(target_, ec)) fs::rename(old, target_, ec);  // the previous result stays
    throw WriteFailure(target_, cause_of(e.code().value()) + " (moving the finished result into place)");
  }
  committed_ = true;
  sync_folder(target_.has_parent_path() ? target_.parent_path() : fs::path("."));
  if (had_previous) fs::remove_all(old, ec);
}

}  // namespace ffp
