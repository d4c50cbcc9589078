#pragma once
/// The particle fields every MPM kind writes for ParaView: fields/particles_NNNN.vtu,
/// one per output time, listed with their times in fields/particles.pvd.
///
/// Arrays of each file, in this order: body; σ_rr, σ_zz, σ_θθ, σ_rz (kPa) when the kind
/// asks for them; p' and q (kPa); the accumulated deviatoric strain; the kind's extra
/// scalars; the density (kg/m³); then the vectors velocity (m/s) and displacement (m).
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "drivers/output/vtu_writer.hpp"
#include "mpm/micropolar.hpp"
#include "mpm/particles.hpp"
#include "mpm/simulation.hpp"

namespace ffp {

/// What a kind adds to the shared arrays.
struct ParticleFieldColumns {
  bool stress_components = false;  ///< sigma_rr/zz/tt/rz_kPa after `body`
  /// One value per particle each, after `deviatoric_strain` (e.g. the plastic deviatoric strain).
  std::vector<std::pair<std::string, std::vector<double>>> extra;
};

/// A micropolar run's extra columns (none for a classical one): the micro-rotation ω and the
/// relative rotation ω_M − ω (rad), the skew stress s (kPa) and the couple stresses' magnitude
/// |m| (N/m) (docs/theory.md#micropolar).
std::vector<std::pair<std::string, std::vector<double>>> micropolar_columns(const mpm::MicropolarFields& fields);

/// A saturated model's columns besides the effective stress (none for a dry one): the pore
/// pressure p (gauge), its excess over hydrostatic (kPa) and the porosity.
std::vector<std::pair<std::string, std::vector<double>>> pore_fluid_columns(const mpm::Simulation& simulation);

/// The numbered field files of one run and their .pvd index.
class ParticleFieldSeries {
 public:
  /// `dir` (created if missing) holds the files.
  explicit ParticleFieldSeries(std::filesystem::path dir);

  /// Writes particles_NNNN.vtu (NNNN = the files written so far) for time `time_s`.
  void write(const mpm::Particles& particles, double time_s, const ParticleFieldColumns& columns = {});

  std::size_t size() const { return pvd_.size(); }
  /// particles.pvd, when at least one file was written.
  void finish() const;

 private:
  std::filesystem::path dir_;
  PvdIndex pvd_;
};

}  // namespace ffp
