#pragma once
/// Running another program (gnuplot, sbatch, squeue) without a shell: its
/// arguments reach it as they are, whatever characters a path holds, so no
/// quoting rule (the shell's or the tool's) can drop or reinterpret one.
#include <string>
#include <string_view>
#include <vector>

namespace ffp {

struct ProgramOutput {
  /// The program's exit code; 128 + N when signal N ended it; -1 when it could not be started.
  int status = -1;
  std::string out;  ///< all it wrote to standard output
  std::string err;  ///< all it wrote to standard error (why it could not start, when status is -1)
};

/// Runs argv[0] (looked up on PATH) with `argv`, `input` as its standard input,
/// and waits for it. Standard input and error go through in-memory files and
/// standard output through a pipe read to its end: neither side can block the
/// other, however much either writes.
ProgramOutput run_program(const std::vector<std::string>& argv, std::string_view input = {});

}  // namespace ffp
