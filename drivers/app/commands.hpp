#pragma once
/// The `ffp` subcommands. Each returns the process exit code:
/// 0 done, 1 run failed, 2 bad input, 130 interrupted.
#include <string>
#include <vector>

namespace ffp {

using Arguments = std::vector<std::string>;

int command_run(const Arguments& args);
int command_check(const Arguments& args);
int command_sweep(const Arguments& args);
int command_collect(const Arguments& args);
int command_report(const Arguments& args);
int command_bench(const Arguments& args);

/// "ffp 0.1.0 (git abc123)"
std::string version_string();

}  // namespace ffp
