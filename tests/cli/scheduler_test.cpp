/// Sweeps handed to a scheduler: `ffp sweep --emit` writes the cases and the
/// launch files, GNU parallel or a real Slurm runs them, and `ffp collect`
/// gives the same sweep.csv as the local pool. Six 2 cm FFP runs (a second
/// each). The Slurm test starts a one-node cluster (scripts/slurm_local.sh,
/// root and Debian's slurm-wlm) and is skipped, with the reason, where it cannot.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli_harness.hpp"

using namespace ffp::test;
namespace fs = std::filesystem;

namespace {

const std::vector<std::string> kSweep = {"--set", "mesh.min_cell_m=0.02",   "--set", "material.E_kPa=1000,2500,5000",
                                         "--set", "contact.delta_deg=15,25"};

std::string reference_scene() { return std::string(FFP_SOURCE_DIR) + "/data/scenes/ffp_reference.json"; }

std::vector<std::string> sweep_args(std::vector<std::string> extra) {
  std::vector<std::string> args = {"sweep", reference_scene()};
  args.insert(args.end(), kSweep.begin(), kSweep.end());
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

using Table = std::vector<std::map<std::string, std::string>>;

/// One record of RFC 4180 CSV (section 2): fields split at the commas outside double quotes, a quoted
/// field's doubled quotes read as one. (No field of these tables spans lines.)
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t k = 0; k < line.size(); ++k) {
    const char c = line[k];
    if (quoted && c == '"' && k + 1 < line.size() && line[k + 1] == '"') {
      fields.back() += '"';
      ++k;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

Table read_table(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::vector<std::string> header;
  Table rows;
  if (std::getline(in, line)) header = csv_fields(line);
  while (std::getline(in, line)) {
    const auto cells = csv_fields(line);
    REQUIRE(cells.size() == header.size());
    std::map<std::string, std::string> row;
    for (std::size_t k = 0; k < header.size() && k < cells.size(); ++k) row[header[k]] = cells[k];
    rows.push_back(row);
  }
  return rows;
}

/// Equal but for where the runs were written and how long they took.
void same_results(const Table& local, const Table& scheduled) {
  REQUIRE(local.size() == scheduled.size());
  REQUIRE_FALSE(local.empty());
  for (std::size_t i = 0; i < local.size(); ++i) {
    INFO("row " << i);
    CHECK(local[i].size() == scheduled[i].size());
    for (const auto& [key, value] : local[i]) {
      if (key == "out_dir" || key == "wall_time_s") continue;
      INFO("column " << key);
      CHECK(scheduled[i].count(key) == 1);
      if (scheduled[i].count(key)) CHECK(scheduled[i].at(key) == value);
    }
  }
}

int shell(const std::string& command) { return std::system(command.c_str()); }

/// The one-node test cluster, started if it is not running (scripts/slurm_local.sh); false where it cannot run.
bool slurm_cluster_up() {
  const std::string start = "bash " + std::string(FFP_SOURCE_DIR) + "/scripts/slurm_local.sh start > /dev/null 2>&1";
  return shell("command -v sbatch > /dev/null 2>&1") == 0 && shell(start) == 0;
}

}  // namespace

TEST_CASE("sweep --emit writes six cases and collect lists them all missing before any ran", "[cli][scheduler]") {
  Scratch scratch;
  const fs::path dir = scratch.path() / "cases";
  const CommandResult emitted = run_ffp(sweep_args({"--emit", dir.string()}), scratch.path());
  INFO(emitted.err);
  REQUIRE(emitted.exit_code == 0);
  for (const char* file : {"cases.tsv", "run_case.sh", "slurm.sbatch", "parallel.sh", "scenes/case_0005.json"})
    CHECK(fs::exists(dir / file));
  std::ifstream sbatch(dir / "slurm.sbatch");
  const std::string text((std::istreambuf_iterator<char>(sbatch)), std::istreambuf_iterator<char>());
  CHECK(text.find("#SBATCH --array=0-5") != std::string::npos);
  const CommandResult collected = run_ffp({"collect", dir.string()}, scratch.path());
  CHECK(collected.exit_code == 1);
  CHECK(collected.err.find("6 missing") != std::string::npos);
  CHECK(run_ffp({"collect", scratch.path().string()}, scratch.path()).exit_code == 2);  // not a case folder
}

TEST_CASE("a case that fails is listed with its error and a rerun of run_case.sh skips a finished one",
          "[cli][scheduler]") {
  Scratch scratch;
  const fs::path dir = scratch.path() / "cases";
  // 200 m/s goes through the 0.4 m chamber: that run ends with exit 1 and says why.
  const CommandResult emitted = run_ffp({"sweep", reference_scene(), "--set", "mesh.min_cell_m=0.02", "--set",
                                         "ffp.impact_velocity_m_s=5.6,200", "--emit", dir.string()},
                                        scratch.path());
  REQUIRE(emitted.exit_code == 0);
  CHECK(shell("OMP_NUM_THREADS=1 bash " + (dir / "run_case.sh").string() + " 0 > /dev/null 2>&1") == 0);
  CHECK(shell("OMP_NUM_THREADS=1 bash " + (dir / "run_case.sh").string() + " 1 > /dev/null 2>&1") != 0);
  const CommandResult collected = run_ffp({"collect", dir.string()}, scratch.path());
  INFO(collected.err);
  CHECK(collected.exit_code == 1);
  CHECK(collected.err.find("case 0001 (mesh.min_cell_m=0.02 ffp.impact_velocity_m_s=200): failed (exit 1)") !=
        std::string::npos);
  CHECK(collected.err.find("went through the chamber") != std::string::npos);
  CHECK(collected.err.find("1 finished, 1 failed, 0 missing") != std::string::npos);
  // A finished case is not run again.
  const fs::path summary = dir / "runs" / "case_0000" / "summary.json";
  const auto written = fs::last_write_time(summary);
  CHECK(shell("bash " + (dir / "run_case.sh").string() + " 0 > /dev/null 2>&1") == 0);
  CHECK(fs::last_write_time(summary) == written);
}

TEST_CASE("GNU parallel runs the emitted cases and collect gives the local sweep's table", "[cli][scheduler]") {
  if (shell("command -v parallel > /dev/null 2>&1") != 0) {
    WARN("skipped: GNU parallel is not installed (bash scripts/setup.sh --tests installs it)");
    return;
  }
  Scratch scratch;
  const fs::path dir = scratch.path() / "cases";
  REQUIRE(run_ffp(sweep_args({"--emit", dir.string()}), scratch.path()).exit_code == 0);
  CHECK(shell("bash " + (dir / "parallel.sh").string() + " 2 > /dev/null 2>&1") == 0);
  CHECK(fs::exists(dir / "logs" / "parallel.joblog"));
  const CommandResult collected = run_ffp({"collect", dir.string()}, scratch.path());
  INFO(collected.err);
  REQUIRE(collected.exit_code == 0);
  const CommandResult local =
      run_ffp(sweep_args({"--jobs", "2", "--out", (scratch.path() / "local").string()}), scratch.path());
  REQUIRE(local.exit_code == 0);
  same_results(read_table(scratch.path() / "local" / "sweep.csv"), read_table(dir / "sweep.csv"));
}

TEST_CASE("a real one-node Slurm runs the sweep as a job array and the collected table equals the local one",
          "[cli][scheduler][slurm]") {
  if (!slurm_cluster_up()) {
    WARN(
        "skipped: no Slurm here (needs root and Debian's slurm-wlm and munge: bash scripts/setup.sh --tests; "
        "scripts/slurm_local.sh start says why it cannot start)");
    return;
  }
  Scratch scratch;
  // A folder name that sbatch's own parsing of #SBATCH lines and its filename patterns would change.
  const fs::path folder = scratch.path() / "slurm it's \"q\" #1 $HOME 50% \\ x";
  const CommandResult slurm = run_ffp(sweep_args({"--scheduler", "slurm", "--out", folder.string()}), scratch.path());
  INFO(slurm.err);
  REQUIRE(slurm.exit_code == 0);
  CHECK(slurm.err.find("Slurm job") != std::string::npos);
  CHECK(fs::exists(folder / "logs" / "case_0005.exit"));
  const CommandResult local =
      run_ffp(sweep_args({"--jobs", "2", "--out", (scratch.path() / "local").string()}), scratch.path());
  REQUIRE(local.exit_code == 0);
  same_results(read_table(scratch.path() / "local" / "sweep.csv"), read_table(folder / "sweep.csv"));
}

TEST_CASE("report with the Slurm scheduler runs its uncached runs as a job array and reads them back",
          "[cli][scheduler][slurm]") {
  if (!slurm_cluster_up()) {
    WARN(
        "skipped: no Slurm here (needs root and Debian's slurm-wlm and munge: bash scripts/setup.sh --tests; "
        "scripts/slurm_local.sh start says why it cannot start)");
    return;
  }
  Scratch scratch;
  const std::string scenes = std::string(FFP_SOURCE_DIR) + "/data/scenes";
  auto report = [&](const std::string& name, std::vector<std::string> extra) {
    std::vector<std::string> args = {"report",
                                     "--scenes",
                                     scenes,
                                     "--only",
                                     "Constitutive integration",
                                     "--out",
                                     (scratch.path() / name / "report").string(),
                                     "--cache",
                                     (scratch.path() / name / "cache").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_ffp(args, scratch.path());
  };
  const CommandResult slurm = report("slurm", {"--scheduler", "slurm"});
  INFO(slurm.err);
  REQUIRE(slurm.exit_code == 0);
  CHECK(slurm.err.find("Slurm job") != std::string::npos);
  // The run came back through the cache like a local one: listed as ok, not failed.
  std::ifstream md(scratch.path() / "slurm" / "report" / "report.md");
  const std::string text((std::istreambuf_iterator<char>(md)), std::istreambuf_iterator<char>());
  CHECK(text.find("| integration_error | ok |") != std::string::npos);
  CHECK(text.find("FAILED") == std::string::npos);
}

TEST_CASE("an inverse fit with the Slurm scheduler runs each batch as a job array and fits as a local one",
          "[cli][scheduler][slurm][inverse]") {
  if (!slurm_cluster_up()) {
    WARN(
        "skipped: no Slurm here (needs root and Debian's slurm-wlm and munge: bash scripts/setup.sh --tests; "
        "scripts/slurm_local.sh start says why it cannot start)");
    return;
  }
  Scratch scratch;
  auto fit = [&](const std::string& name, const std::string& scheduler) {
    return run_ffp({"run", std::string(FFP_SOURCE_DIR) + "/data/scenes/inverse_experiment.json", "--out",
                    (scratch.path() / name).string(), "--quiet", "--scheduler", scheduler, "--set",
                    "forward_overrides=[\"mesh.min_cell_m=0.02\",\"end_time_s=0.05\"]", "--set", "max_iterations=1"},
                   scratch.path());
  };
  const CommandResult slurm = fit("slurm", "slurm");
  INFO(slurm.err);
  REQUIRE(slurm.exit_code == 0);
  CHECK(slurm.err.find("Slurm job") != std::string::npos);
  const CommandResult local = fit("local", "local");
  REQUIRE(local.exit_code == 0);
  auto summary = [&](const std::string& name) {
    std::ifstream in(scratch.path() / name / "summary.json");
    return nlohmann::json::parse(in);
  };
  const auto a = summary("slurm"), b = summary("local");
  CHECK(a["scheduler"] == "slurm");
  // The model runs are deterministic, so the two fits take the same steps to the same value (one
  // iteration of short runs: what is tested is the batches' way through Slurm, not the fit).
  CHECK(a["parameters"]["material.phi_peak_deg"]["value"] == b["parameters"]["material.phi_peak_deg"]["value"]);
  CHECK(a["model_runs"] == b["model_runs"]);
}

namespace {

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::size_t lines(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

/// bash DIR/run_case.sh K, one OpenMP thread; its exit code.
int run_case(const fs::path& dir, int k) {
  return shell("OMP_NUM_THREADS=1 bash " + (dir / "run_case.sh").string() + " " + std::to_string(k) +
               " > /dev/null 2>&1");
}

/// The point scene of the harness (a triaxial MC run of 50 increments, a fraction of a second).
fs::path point_scene(const Scratch& scratch) { return scratch.write_json("point.json", ffp::test::good_point_scene()); }

}  // namespace

TEST_CASE("a folder emitted again with other values never relabels a finished case", "[cli][scheduler]") {
  Scratch scratch;
  const fs::path scene = point_scene(scratch), dir = scratch.path() / "cases";
  auto emit = [&](const std::string& values, std::vector<std::string> extra = {}) {
    std::vector<std::string> args = {"sweep",  scene.string(), "--set", "material.E_kPa=" + values,
                                     "--emit", dir.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_ffp(args, scratch.path());
  };
  REQUIRE(emit("1000,2000").exit_code == 0);
  REQUIRE(run_case(dir, 0) == 0);
  const fs::path finished = dir / "runs" / "case_0000" / "summary.json";
  const auto written = fs::last_write_time(finished);

  // The same values again: the finished case is kept as it is.
  const CommandResult same = emit("1000,2000");
  INFO(same.err);
  REQUIRE(same.exit_code == 0);
  CHECK(fs::last_write_time(finished) == written);

  // Other values: refused in one line naming the case, the key, both values and the way out; nothing changed.
  const std::string cases_before = read_text(dir / "cases.tsv");
  const CommandResult other = emit("50000,60000");
  INFO(other.err);
  CHECK(other.exit_code == 2);
  CHECK(lines(other.err) == 1);
  for (const char* word : {"case 0000", "material.E_kPa = 1000", "50000", "--force"})
    CHECK(other.err.find(word) != std::string::npos);
  CHECK(read_text(dir / "cases.tsv") == cases_before);
  CHECK(fs::last_write_time(finished) == written);

  // --force: the case that ran 1000 is discarded and both run afresh under their new values.
  const CommandResult forced = emit("50000,60000", {"--force"});
  INFO(forced.err);
  REQUIRE(forced.exit_code == 0);
  CHECK_FALSE(fs::exists(dir / "runs" / "case_0000"));
  REQUIRE(run_case(dir, 0) == 0);
  REQUIRE(run_case(dir, 1) == 0);
  const CommandResult collected = run_ffp({"collect", dir.string()}, scratch.path());
  INFO(collected.err);
  REQUIRE(collected.exit_code == 0);
  // Each row's figures are those of a run with its own E' (MC triaxial: the axial strain at peak scales with 1/E').
  const CommandResult direct =
      run_ffp({"run", scene.string(), "--out", "direct", "--quiet", "--set", "material.E_kPa=50000"}, scratch.path());
  REQUIRE(direct.exit_code == 0);
  const nlohmann::json expected = nlohmann::json::parse(read_text(scratch.path() / "direct" / "summary.json"));
  const Table table = read_table(dir / "sweep.csv");
  REQUIRE(table.size() == 2);
  CHECK(table[0].at("material.E_kPa") == "50000");
  char strain[32];
  std::snprintf(strain, sizeof strain, "%.10g", expected["axial_strain_at_peak"].get<double>());
  CHECK(table[0].at("axial_strain_at_peak") == strain);
  for (const auto& row : table) {
    const nlohmann::json ran = nlohmann::json::parse(read_text(scratch.path() / row.at("out_dir") / "summary.json"));
    CHECK(ran["scene"]["material"]["E_kPa"].get<double>() == std::stod(row.at("material.E_kPa")));
  }
}

TEST_CASE("a failure logged under other values is not reported for the case emitted in its place", "[cli][scheduler]") {
  Scratch scratch;
  const fs::path dir = scratch.path() / "cases";
  auto emit = [&](const std::string& velocities) {
    return run_ffp({"sweep", reference_scene(), "--set", "mesh.min_cell_m=0.02", "--set",
                    "ffp.impact_velocity_m_s=" + velocities, "--emit", dir.string()},
                   scratch.path());
  };
  REQUIRE(emit("5.6,200").exit_code == 0);
  REQUIRE(run_case(dir, 1) != 0);  // 200 m/s goes through the chamber
  REQUIRE(fs::exists(dir / "logs" / "case_0001.exit"));
  REQUIRE(emit("5.6,6").exit_code == 0);  // nothing finished differs: no refusal
  const CommandResult collected = run_ffp({"collect", dir.string()}, scratch.path());
  INFO(collected.err);
  CHECK(collected.exit_code == 1);
  CHECK(collected.err.find("case 0001 (mesh.min_cell_m=0.02 ffp.impact_velocity_m_s=6): missing") != std::string::npos);
  CHECK(collected.err.find("through the chamber") == std::string::npos);
}

TEST_CASE("a key given twice to sweep is refused in one line naming it, before anything is written",
          "[cli][scheduler]") {
  Scratch scratch;
  const fs::path scene = point_scene(scratch);
  const CommandResult r = run_ffp({"sweep", scene.string(), "--set", "material.E_kPa=1000,2000", "--set",
                                   "material.nu=0.3", "--set", "material.E_kPa=3000", "--emit", "cases"},
                                  scratch.path());
  CHECK(r.exit_code == 2);
  CHECK(lines(r.err) == 1);
  CHECK(r.err.find("--set material.E_kPa: given twice") != std::string::npos);
  CHECK_FALSE(fs::exists(scratch.path() / "cases"));
}

TEST_CASE("sweep.csv quotes a field holding a comma, so every row has the header's fields", "[cli][scheduler]") {
  Scratch scratch;
  const fs::path scene = point_scene(scratch);
  const CommandResult r =
      run_ffp({"sweep", scene.string(), "--set", "material.E_kPa=1000,2000", "--out", "runs,2024"}, scratch.path());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const std::string text = read_text(scratch.path() / "runs,2024" / "sweep.csv");
  CHECK(text.find("\"runs,2024/runs/") != std::string::npos);                  // RFC 4180: the field in double quotes
  const Table table = read_table(scratch.path() / "runs,2024" / "sweep.csv");  // requires the header's count
  REQUIRE(table.size() == 2);
  for (const auto& row : table) CHECK(fs::exists(scratch.path() / row.at("out_dir") / "summary.json"));
}

TEST_CASE("collect names every case whose summary is missing or corrupt, with its file and the reason",
          "[cli][scheduler]") {
  Scratch scratch;
  const fs::path scene = point_scene(scratch), dir = scratch.path() / "cases";
  REQUIRE(run_ffp({"sweep", scene.string(), "--set", "material.E_kPa=1000,2000,3000", "--emit", dir.string()},
                  scratch.path())
              .exit_code == 0);
  for (int k = 0; k < 3; ++k) REQUIRE(run_case(dir, k) == 0);
  std::ofstream(dir / "runs" / "case_0000" / "summary.json", std::ios::trunc) << "{\"peak_q_kPa\": 3.4,";
  fs::remove(dir / "runs" / "case_0002" / "summary.json");
  const CommandResult collected = run_ffp({"collect", dir.string()}, scratch.path());
  INFO(collected.err);
  CHECK(collected.exit_code == 1);
  const std::string corrupt =
      "case 0000 (material.E_kPa=1000): unusable: " + (dir / "runs" / "case_0000" / "summary.json").string() +
      ": corrupt (parse error";
  const std::string missing =
      "case 0002 (material.E_kPa=3000): unusable: " + (dir / "runs" / "case_0002" / "summary.json").string() +
      ": missing";
  CHECK(collected.err.find(corrupt) != std::string::npos);
  CHECK(collected.err.find(missing) != std::string::npos);
  CHECK(collected.err.find("[json.exception") == std::string::npos);  // the parser's reason, not its tag
  CHECK(collected.err.find("1 finished, 0 failed, 0 missing, 2 unusable") != std::string::npos);
  // The table keeps every case; only the good one has figures and an exit code.
  const Table table = read_table(dir / "sweep.csv");
  REQUIRE(table.size() == 3);
  CHECK(table[0].at("exit_code").empty());
  CHECK(table[0].at("peak_q_kPa").empty());
  CHECK(table[1].at("exit_code") == "0");
  CHECK_FALSE(table[1].at("peak_q_kPa").empty());
  CHECK(table[2].at("exit_code").empty());
}
