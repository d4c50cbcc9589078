/// Size limits before allocation: the estimate counts exactly the particles and
/// nodes the model will have, and a scene that cannot fit is refused (exit 2,
/// naming the key, the estimate and the usable memory) before it allocates.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>

#include <sys/wait.h>

#include "coarse_ffp.hpp"
#include "ffp_test_support.hpp"
#include "mpm/ffp_model.hpp"
#include "mpm/model_size.hpp"

using namespace ffp;
using namespace ffp::test;
using namespace ffp::mpm;

namespace {

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("the size estimate counts the particles and nodes the FFP model builds", "[ffp][size]") {
  FfpDescription d = coarse_ffp();
  SECTION("rigid penetrometer") {}
  SECTION("deformable penetrometer") { d.deformable = DeformableFfp{}; }
  SECTION("denser seeding near the axis") {
    d.soil.near_ppc_r = 4;
    d.soil.near_ppc_z = 5;
  }
  const ModelSize size = estimate_ffp_size(d, 1e12);
  const FfpRun run(d);
  CHECK_FALSE(size.particles_at_least);
  CHECK(size.particles == run.simulation().particles.size());
  CHECK(size.nodes == run.simulation().grid.nodes());
}

TEST_CASE("the size estimate stops counting once past its budget", "[ffp][size]") {
  FfpDescription d = coarse_ffp();
  d.mesh.min_cell_m = 5e-4;  // ~10^6 nodes (0.5 GB) and millions of particles: counted up to the budget
  d.mesh.max_cell_m = 1.5e-3;
  d.mesh.below_cell_m = 1e-3;
  d.mesh.min_compressed_cell_m = 5e-4;
  const ModelSize size = estimate_ffp_size(d, 1e9);
  REQUIRE(static_cast<double>(size.nodes) * ModelSize::kBytesPerNode < 0.9e9);
  CHECK(size.particles_at_least);
  CHECK(size.particles > 100000);
  CHECK(size.bytes() > 1e9);
  CHECK(size.bytes() < 1e9 + 2 * ModelSize::kBytesPerParticle);
}

TEST_CASE("an FFP mesh that cannot fit in memory is refused before allocation, naming the key", "[ffp][size]") {
  ScratchDir scratch;
  const ProgramResult r =
      run_program({"check", scene_path("ffp_reference.json"), "--set", "mesh.min_cell_m=1e-5"}, scratch.path());
  INFO(r.err);
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("mesh.min_cell_m") != std::string::npos);
  CHECK(r.err.find("GB") != std::string::npos);
  CHECK(r.err.find("usable") != std::string::npos);
}

// AddressSanitizer reserves terabytes of address space at start-up, so a program
// built with it cannot run under `ulimit -v` at all: this check exists only in
// builds without it (the limit's logic is the same code in both).
#ifndef __SANITIZE_ADDRESS__
TEST_CASE("under a 3 GB address-space limit a 0.25 mm FFP mesh is refused and ffp check prints the estimate",
          "[ffp][size]") {
  ScratchDir scratch;
  const std::string base = "cd '" + scratch.path().string() + "' && ulimit -v 3000000 && '" + FFP_BINARY + "' check '" +
                           scene_path("ffp_reference.json") + "'";
  const int refused = std::system((base + " --set mesh.min_cell_m=2.5e-4 > out.txt 2> err.txt").c_str());
  const std::string err = read_text(scratch.path() / "err.txt");
  INFO(err);
  CHECK(WEXITSTATUS(refused) == 2);
  CHECK(err.find("ulimit -v") != std::string::npos);
  const int fits = std::system((base + " > out.txt 2> err.txt").c_str());
  CHECK(WEXITSTATUS(fits) == 0);
  CHECK(read_text(scratch.path() / "out.txt").find("memory: about") != std::string::npos);
}
#endif

TEST_CASE("ffp check prints the memory estimate for every MPM kind", "[ffp][size]") {
  ScratchDir scratch;
  for (const char* scene : {"ffp_reference.json", "cpt_reference.json", "mpm_wave_column.json", "ffp_elastic.json",
                            "calibration_dr15_mpm_1cm.json"}) {
    const ProgramResult r = run_program({"check", scene_path(scene)}, scratch.path());
    INFO(scene << ": " << r.err);
    CHECK(r.exit_code == 0);
    CHECK(r.out.find("memory: about") != std::string::npos);
  }
}

TEST_CASE("an MPM calibration specimen too fine to fit is refused before any run, naming specimen.cell_m",
          "[ffp][size]") {
  ScratchDir scratch;
  const ProgramResult r = run_program(
      {"check", scene_path("calibration_dr15_mpm_1cm.json"), "--set", "specimen.cell_m=1e-5"}, scratch.path());
  INFO(r.err);
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("specimen.cell_m") != std::string::npos);
}
