/// Reading lab curves: the reconstructed files load, and every kind of bad file
/// is one clear SceneError naming the file, the line and what is allowed.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include <catch2/catch.hpp>

#include "calibration/lab_curve.hpp"
#include "drivers/scene/scene_error.hpp"
#include "models/math_constants.hpp"
#include "tests/support/scratch.hpp"

using namespace ffp;
namespace fs = std::filesystem;

namespace {

/// This file's scratch folders are named ffp-lab-….
struct Scratch : ffp::test_support::Scratch {
  Scratch() : ffp::test_support::Scratch("ffp-lab") {}
};

/// The message of the SceneError reading `text` throws ("" if none).
std::string error_of(const Scratch& dir, const std::string& text) {
  const fs::path file = dir.write("lab.csv", text);
  try {
    read_lab_curve(file);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

const std::string kHeader = "# a comment line\naxial_strain,deviatoric_stress_kPa,volumetric_strain\n";
const std::string kRows = "0,0,0\n0.01,3,0.001\n0.02,4,0.001\n0.03,4.5,0\n0.04,4.2,-0.001\n";

}  // namespace

TEST_CASE("the reconstructed lab curves load in SI units", "[calibration][lab]") {
  for (const char* name : {"triaxial_dr00.csv", "triaxial_dr15.csv"}) {
    CAPTURE(name);
    const LabCurve c = read_lab_curve(fs::path(FFP_SOURCE_DIR) / "data" / "lab" / name);
    CHECK(c.axial_strain.size() == 49);
    CHECK(c.axial_strain.front() == 0.0);
    CHECK(c.axial_strain.back() == Approx(0.2));
    CHECK(c.volumetric_strain.size() == 49);
    // Peaks from data/lab/README.md: σ3 (Nφ − 1) for φ'_p = 38° and 40°, with ±1 % noise.
    const double s = std::sin((std::string(name) == "triaxial_dr00.csv" ? 38.0 : 40.0) * kDegree);
    CHECK(c.peak_q_Pa() == Approx(1720.0 * ((1 + s) / (1 - s) - 1)).epsilon(0.01));
  }
}

TEST_CASE("a lab curve without volumetric strain is accepted and other columns are ignored", "[calibration][lab]") {
  Scratch dir;
  const fs::path file = dir.write(
      "lab.csv", "time_s,axial_strain,deviatoric_stress_kPa\n0,0,0\n1,0.01,3\n2,0.02,4\n3,0.03,4.5\n4,0.04,4.2\n");
  const LabCurve c = read_lab_curve(file);
  CHECK(c.volumetric_strain.empty());
  CHECK(c.deviatoric_stress_Pa[3] == Approx(4500.0));
  CHECK(c.axial_strain_at_peak() == Approx(0.03));
}

TEST_CASE("bad lab CSVs: one line naming the file, the line and what is allowed", "[calibration][lab][errors]") {
  Scratch dir;
  REQUIRE(error_of(dir, kHeader + kRows).empty());

  SECTION("missing column") {
    const std::string e = error_of(dir, "axial_strain,q_kPa\n0,0\n0.01,1\n0.02,2\n0.03,3\n0.04,4\n");
    CHECK(e.find("lab.csv") != std::string::npos);
    CHECK(e.find("no column 'deviatoric_stress_kPa'") != std::string::npos);
    CHECK(e.find("the header has: axial_strain, q_kPa") != std::string::npos);
  }
  SECTION("non-numeric cell, with its line") {
    const std::string e = error_of(dir, kHeader + "0,0,0\n0.01,3,0.001\n0.02,four,0.001\n0.03,4.5,0\n0.04,4.2,0\n");
    CHECK(e.find("lab.csv:5") != std::string::npos);
    CHECK(e.find("'four' is not a number") != std::string::npos);
  }
  SECTION("NaN") {
    const std::string e = error_of(dir, kHeader + "0,0,0\n0.01,nan,0.001\n0.02,4,0.001\n0.03,4.5,0\n0.04,4.2,0\n");
    CHECK(e.find("lab.csv:4") != std::string::npos);
    CHECK(e.find("finite") != std::string::npos);
  }
  SECTION("non-monotone strain, with the line it turns at") {
    const std::string e = error_of(dir, kHeader + "0,0,0\n0.01,3,0.001\n\n0.03,4,0.001\n0.02,4.5,0\n0.04,4.2,0\n");
    CHECK(e.find("lab.csv:7") != std::string::npos);  // blank and comment lines counted as an editor does
    CHECK(e.find("must increase strictly") != std::string::npos);
  }
  SECTION("repeated strain") {
    const std::string e = error_of(dir, kHeader + "0,0,0\n0.01,3,0.001\n0.01,4,0.001\n0.03,4.5,0\n0.04,4.2,0\n");
    CHECK(e.find("lab.csv:5") != std::string::npos);
    CHECK(e.find("does not increase") != std::string::npos);
  }
  SECTION("fewer than 5 points") {
    const std::string e = error_of(dir, kHeader + "0,0,0\n0.01,3,0.001\n0.02,4,0.001\n0.03,4.5,0\n");
    CHECK(e.find("has 4 data row(s)") != std::string::npos);
    CHECK(e.find("at least 5") != std::string::npos);
  }
  SECTION("empty file") {
    const std::string e = error_of(dir, "");
    CHECK(e.find("lab.csv") != std::string::npos);
    CHECK(e.find("empty") != std::string::npos);
  }
  SECTION("a header and no data") { CHECK(error_of(dir, kHeader).find("has 0 data row(s)") != std::string::npos); }
  SECTION("negative strain (extension, or the wrong sign convention)") {
    const std::string e = error_of(dir, kHeader + "-0.01,0,0\n0.01,3,0.001\n0.02,4,0.001\n0.03,4.5,0\n0.04,4.2,0\n");
    CHECK(e.find("lab.csv:3") != std::string::npos);
    CHECK(e.find("compression positive") != std::string::npos);
  }
  SECTION("strain in percent") {
    CHECK(error_of(dir, kHeader + "0,0,0\n1,3,0\n2,4,0\n3,4.5,0\n4,4.2,0\n").find("not a percentage") !=
          std::string::npos);
  }
  SECTION("no positive deviatoric stress") {
    CHECK(error_of(dir, kHeader + "0,0,0\n0.01,-3,0\n0.02,-4,0\n0.03,-4.5,0\n0.04,-4.2,0\n").find("never above 0") !=
          std::string::npos);
  }
  SECTION("a missing file") { CHECK_THROWS_AS(read_lab_curve(dir.path / "absent.csv"), SceneError); }
  SECTION("ragged row") {
    CHECK(error_of(dir, kHeader + "0,0,0\n0.01,3\n0.02,4,0\n0.03,4.5,0\n0.04,4.2,0\n").find("lab.csv:4") !=
          std::string::npos);
  }
}
