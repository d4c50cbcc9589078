/// The command line: every subcommand and option declared once, to CLI11, which
/// also writes the help (`ffp --help`, `ffp run --help`, …).
#include <cstdio>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "drivers/app/commands.hpp"

namespace ffp {

namespace {

constexpr const char* kFooter = R"(
Examples:
  ffp run SCENE.json [--out DIR] [--set key=value ...]    one run into DIR (default results/<scene name>)
  ffp check SCENE.json                                    validate, print the scene with its defaults
  ffp sweep SCENE.json --set key=v1,v2 [--emit DIR]       every combination, here or for a scheduler
  ffp report [--out DIR]                                  the validation study and its report
  ffp keys [KIND] [--markdown]                            every scene key: meaning, unit, default, range
Each command has its own help: ffp run --help.

Scene kinds: point, triaxial, calibration, integration_error, mpm, ffp, cpt, record, inverse
(ffp keys KIND lists a kind's keys).
Exit codes: 0 done, 1 run failed, 2 bad input, 130 interrupted.)";

/// --scheduler local|slurm, where a command's runs go; `help` says what slurm does for it.
void add_scheduler(CLI::App& command, bool& slurm, const std::string& help) {
  command
      .add_option_function<std::string>(
          "--scheduler", [&slurm](const std::string& s) { slurm = s == "slurm"; }, help)
      ->check(CLI::IsMember({"local", "slurm"}));
}

void add_scene(CLI::App& command, RunOptions& o) {
  command.add_option("SCENE", o.scene_file, "the scene file (JSON)")->required();
  command.add_option("--set", o.overrides, "override a scene key, e.g. --set material.E_kPa=5000 (repeatable)")
      ->type_name("KEY=VALUE")
      ->allow_extra_args(false);
  command.add_flag("-q,--quiet", o.quiet, "no progress on stderr");
}

void add_run(CLI::App& app, RunOptions& o) {
  CLI::App& run = *app.add_subcommand("run", "Run a scene; write DIR/summary.json, DIR/history.csv, DIR/plots/");
  add_scene(run, o);
  run.add_option("--out", o.out, "output folder (default results/<scene name>)")->type_name("DIR");
  run.add_flag("--force", o.force, "replace an --out folder that holds files ffp did not write");
  run.add_flag("--allow-long", o.allow_long,
               "run an MPM scene whose estimated wall time (ffp check prints it) is above a day; "
               "FFP_ALLOW_LONG=1 in the environment does the same");
  run.add_option("--jobs", o.jobs,
                 "an inverse fit's or a meshed calibration's model runs at once (default one per core)")
      ->check(CLI::Range(1, 64));
  add_scheduler(run, o.slurm, "where an inverse fit's model runs go: local (default) or slurm (job arrays)");
}

void add_check(CLI::App& app, RunOptions& o) {
  CLI::App& check = *app.add_subcommand("check", "Validate a scene and print it with defaults filled in");
  add_scene(check, o);
}

void add_sweep(CLI::App& app, SweepOptions& o) {
  CLI::App& sweep = *app.add_subcommand(
      "sweep", "Run every combination of --set key=v1,v2,... as an independent process; DIR/sweep.csv");
  sweep.add_option("SCENE", o.scene_file, "the scene file (JSON)")->required();
  sweep.add_option("--set", o.axes, "a key and its values, key=v1,v2,... (repeatable, one --set per key)")
      ->type_name("KEY=V1,V2")
      ->required()
      ->allow_extra_args(false);
  sweep.add_option("--out", o.out, "output folder (default results/<scene name>-sweep)")->type_name("DIR");
  sweep
      .add_option("--emit", o.emit,
                  "write the cases for a scheduler instead (DIR/cases.tsv, one scene per case, slurm.sbatch, "
                  "parallel.sh)")
      ->type_name("DIR");
  sweep.add_option("--jobs", o.jobs, "runs side by side (default 1)")->check(CLI::Range(1, 256));
  sweep.add_option("--threads", o.threads, "OpenMP threads per case (default 1)")->check(CLI::Range(1, 256));
  sweep.add_flag("--force", o.force,
                 "use a folder that holds files ffp did not write; with --emit, also discard the finished cases "
                 "that ran other scenes, so that they run afresh");
  sweep.add_flag("--allow-long", o.allow_long, "let each case run even if estimated above a day (see ffp run --help)");
  add_scheduler(sweep, o.slurm, "local (default) or slurm: submit the emitted job array with sbatch, wait, collect");
}

void add_collect(CLI::App& app, std::filesystem::path& folder) {
  CLI::App& collect = *app.add_subcommand(
      "collect",
      "Build DIR/sweep.csv from an emitted sweep's finished cases; list the missing and failed ones "
      "(exit 1 while any is)");
  collect.add_option("DIR", folder, "a folder written by ffp sweep --emit (or --scheduler slurm)")->required();
}

void add_report(CLI::App& app, ReportOptions& o) {
  CLI::App& report =
      *app.add_subcommand("report", "Run the validation study (cached) and write DIR/report.md with figures");
  report.add_option("--out", o.out, "report folder (default report)")->type_name("DIR");
  report.add_option("--cache", o.cache, "run cache (default results/cache)")->type_name("DIR");
  report.add_option("--scenes", o.scenes, "folder of the scenes (default data/scenes)")->type_name("DIR");
  report.add_option("--only", o.only, "only the studies whose title contains TEXT");
  report.add_option("--jobs", o.jobs, "runs side by side (default one per core)")->check(CLI::Range(1, 64));
  report.add_flag("--force", o.force, "replace a folder that holds files ffp did not write");
  add_scheduler(report, o.slurm, "local (default) or slurm: the uncached runs as Slurm job arrays");
}

void add_bench(CLI::App& app, BenchOptions& o) {
  CLI::App& bench =
      *app.add_subcommand("bench", "Measure the end-to-end speed of representative scenes (median of repeats)");
  bench.add_option("--repeat", o.repeats, "runs of each scene (default 3)")->check(CLI::Range(1, 100));
  bench.add_option("--scenes", o.scenes, "folder of the scenes (default data/scenes)")->type_name("DIR");
}

void add_keys(CLI::App& app, KeysOptions& o) {
  CLI::App& keys = *app.add_subcommand(
      "keys", "Print every key a scene of each kind accepts: meaning, unit, default, range, and the keys it needs");
  keys.add_option("KIND", o.kind, "only this kind's keys (default: every kind)");
  keys.add_flag("--markdown", o.markdown,
                "Markdown tables, one per kind and per nested object (docs/reference/scenes.md)");
}

}  // namespace

int run_command_line(int argc, char** argv) {
  CLI::App app{"ffp: sand constitutive-model testbed and axisymmetric MPM solver for free-fall penetrometer impacts",
               "ffp"};
  app.require_subcommand(1);
  app.set_version_flag("--version", version_string());
  RunOptions run, check;
  SweepOptions sweep;
  std::filesystem::path collect;
  ReportOptions report;
  BenchOptions bench;
  KeysOptions keys;
  add_run(app, run);
  add_check(app, check);
  add_sweep(app, sweep);
  add_collect(app, collect);
  add_report(app, report);
  add_bench(app, bench);
  add_keys(app, keys);
  app.footer(kFooter);  // after the subcommands: they would inherit it

  if (argc < 2) {
    std::cerr << app.help();
    return 2;
  }
  const std::string first = argv[1];
  if (first.empty() || first[0] != '-') {
    bool known = false;
    for (const CLI::App* command : app.get_subcommands({})) known = known || command->get_name() == first;
    if (!known) {
      std::fprintf(stderr, "ffp: unknown command '%s' (try ffp --help)\n", first.c_str());
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    const std::string command = app.get_subcommands().empty() ? "" : " " + app.get_subcommands().front()->get_name();
    std::fprintf(stderr, "error: %s (try ffp%s --help)\n", e.what(), command.c_str());
    return 2;
  }
  if (app.got_subcommand("run")) return command_run(run);
  if (app.got_subcommand("check")) return command_check(check);
  if (app.got_subcommand("sweep")) return command_sweep(sweep);
  if (app.got_subcommand("collect")) return command_collect(collect);
  if (app.got_subcommand("report")) return command_report(report);
  if (app.got_subcommand("keys")) return command_keys(keys);
  return command_bench(bench);
}

}  // namespace ffp
