#include "cli_harness.hpp"

#include <algorithm>
#include <fstream>
#include <random>
#include <sstream>

#include <sys/wait.h>
#include <unistd.h>

namespace ffp::test {

namespace fs = std::filesystem;

Scratch::Scratch() {
  std::random_device rd;
  path_ = fs::temp_directory_path() / ("ffp-cli-test-" + std::to_string(::getpid()) + "-" + std::to_string(rd()));
  fs::create_directories(path_);
}

Scratch::~Scratch() {
  std::error_code ignored;
  fs::remove_all(path_, ignored);
}

fs::path Scratch::write(const std::string& name, const std::string& content) const {
  const fs::path file = path_ / name;
  std::ofstream(file, std::ios::binary) << content;
  return file;
}

fs::path Scratch::write_json(const std::string& name, const nlohmann::json& scene) const {
  return write(name, scene.dump(2));
}

std::vector<std::string> Scratch::entries() const {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(path_)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

namespace {
std::string slurp(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string shell_quote(const std::string& word) {
  std::string out = "'";
  for (char c : word) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}
}  // namespace

CommandResult run_ffp(const std::vector<std::string>& args, const fs::path& cwd, const fs::path& stdout_to,
                      const std::string& before) {
  static int counter = 0;
  const std::string tag = std::to_string(::getpid()) + "-" + std::to_string(++counter);
  const fs::path out_file = fs::temp_directory_path() / ("ffp-cli-out-" + tag);
  const fs::path err_file = fs::temp_directory_path() / ("ffp-cli-err-" + tag);
  std::string command = "cd " + shell_quote(cwd.string()) + " && " + before + " " + shell_quote(FFP_BINARY);
  for (const auto& a : args) command += " " + shell_quote(a);
  command += " > " + shell_quote((stdout_to.empty() ? out_file : stdout_to).string()) + " 2> " +
             shell_quote(err_file.string());
  const int status = std::system(command.c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.out = slurp(out_file);
  result.err = slurp(err_file);
  std::error_code ignored;
  fs::remove(out_file, ignored);
  fs::remove(err_file, ignored);
  return result;
}

nlohmann::json good_point_scene() {
  return nlohmann::json::parse(R"({
    "kind": "point",
    "name": "cli_point",
    "material": {"model": "mohr_coulomb", "E_kPa": 2500, "nu": 0.33, "phi_peak_deg": 39},
    "path": {"type": "triaxial_compression", "cell_pressure_kPa": 1.72, "axial_strain_max": 0.05,
             "increments": 50}
  })");
}

}  // namespace ffp::test
