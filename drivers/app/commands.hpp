#pragma once
/// The `ffp` subcommands, each with its options already parsed (command_line.cpp
/// declares them to CLI11). Each returns the process exit code:
/// 0 done, 1 run failed, 2 bad input, 130 interrupted.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ffp {

struct RunOptions {
  std::string scene_file;
  std::vector<std::string> overrides;  ///< --set key=value, in order
  std::optional<std::filesystem::path> out;
  bool quiet = false;
  bool force = false;       ///< replace an --out folder that holds files ffp did not write
  bool allow_long = false;  ///< run an MPM scene estimated above a day (run_cost.hpp)
  int jobs = 0;             ///< an inverse fit's model runs at once (0: one per core)
  bool slurm = false;       ///< an inverse fit's model runs as Slurm job arrays
};

struct SweepOptions {
  std::string scene_file;
  std::vector<std::string> axes;  ///< --set key=v1,v2,...
  std::filesystem::path out, emit;
  int jobs = 1, threads = 1;
  bool force = false, slurm = false;
  bool allow_long = false;  ///< passed to every case's run
};

struct ReportOptions {
  std::filesystem::path out = "report";
  std::filesystem::path cache = "results/cache";
  std::filesystem::path scenes;  ///< empty: data/scenes here, else the source tree's
  std::string only;
  bool force = false, slurm = false;
  int jobs = 0;  ///< 0: one per core
};

struct BenchOptions {
  int repeats = 3;
  std::filesystem::path scenes;  ///< empty: data/scenes here, else the source tree's
};

struct KeysOptions {
  std::string kind;  ///< "" for every kind
  bool markdown = false;
};

int command_run(const RunOptions& options);
int command_check(const RunOptions& options);
int command_sweep(const SweepOptions& options);
int command_collect(const std::filesystem::path& folder);
int command_report(const ReportOptions& options);
int command_bench(const BenchOptions& options);
int command_keys(const KeysOptions& options);

/// Parse the command line (CLI11) and run the subcommand it names.
int run_command_line(int argc, char** argv);

/// "ffp 0.1.0 (git abc123)"
std::string version_string();

/// data/scenes in the working folder if it is there, else the source tree's.
std::filesystem::path default_scenes_folder();

}  // namespace ffp
