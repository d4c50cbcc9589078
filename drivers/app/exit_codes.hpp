#pragma once
/// The program's exit codes and the one place that turns what a command throws
/// into them, so that every subcommand answers alike (docs/outputs.md, "Exit codes"):
///   SceneError (bad input)                          → 2
///   Interrupted (Ctrl-C, SIGTERM)                   → 130
///   RunFailure, std::bad_alloc, any std::exception  → 1
/// A command that was asked to stop says so: a failure that the Ctrl-C caused (a
/// model run it stopped, a write it cut short) gives 130, and so does a command
/// that returns after a Ctrl-C arrived too late for it to poll.
#include <string_view>

namespace ffp {

enum ExitCode : int { kExitDone = 0, kExitRunFailed = 1, kExitBadInput = 2, kExitInterrupted = 130 };

/// Call inside `catch (...)`: one line on stderr for the exception being handled and its exit
/// code. An interruption says "interrupted: <interrupted_note>" (e.g. "no result written"), or
/// "interrupted" alone. A RunFailure that carries a reproducer also leaves failed-step.json in
/// the working folder (a scene that repeats the failing step) and names it.
int exit_code_of_current_exception(std::string_view interrupted_note = {});

/// The exit code of a command that returned `code`: 130 (and "interrupted" on stderr) if a
/// Ctrl-C arrived meanwhile, unless the command refused its input (2) before any work.
int exit_code_after_command(int code);

}  // namespace ffp
