/// The kinds' scene readers called in-process: a shipped scene gives the typed
/// description it spells, and bad input throws a SceneError that names the key
/// and what it may be (the text `ffp` prints on stderr, after "error: ").
#include <cmath>
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "drivers/app/calibration_scene.hpp"
#include "drivers/app/ffp_scene.hpp"
#include "drivers/app/integration_error_scene.hpp"
#include "drivers/app/inverse_scene.hpp"
#include "drivers/app/job.hpp"
#include "drivers/app/mpm_scene.hpp"
#include "drivers/app/record_scene.hpp"
#include "models/math_constants.hpp"
#include "tests/app/shipped_scene.hpp"

using namespace ffp;
using ffp::test_support::scene_error;
using ffp::test_support::ShippedScene;

namespace {

CalibrationScene calibration(const std::string& name, const std::vector<std::string>& overrides = {}) {
  ShippedScene s(name, overrides);
  return read_calibration_scene(s.reader(), s.dir());
}

std::string calibration_error(const std::string& name, const std::string& override_) {
  return scene_error([&] { calibration(name, {override_}); });
}

IntegrationErrorScene integration_error(const std::vector<std::string>& overrides = {}) {
  ShippedScene s("integration_error", overrides);
  return read_integration_error_scene(s.reader());
}

MpmScene mpm_scene(const std::string& name, const std::vector<std::string>& overrides = {}) {
  ShippedScene s(name, overrides);
  return read_mpm_scene(s.reader());
}

FfpScene ffp_scene(const std::string& name, PenetrometerKind kind, const std::vector<std::string>& overrides = {}) {
  ShippedScene s(name, overrides);
  return read_ffp_scene(s.reader(), kind);
}

RecordScene record_scene(const std::vector<std::string>& overrides = {}) {
  ShippedScene s("record_reference", overrides);
  RecordScene out = read_record_scene(s.reader(), s.dir());
  s.reader().finish("a record scene");
  return out;
}

InverseScene inverse_scene(const std::vector<std::string>& overrides = {}) {
  ShippedScene s("inverse_reference", overrides);
  InverseScene out = read_inverse_scene(s.reader(), s.dir());
  s.reader().finish("an inverse scene");
  return out;
}

}  // namespace

TEST_CASE("calibration reader: calibration_dr15 is the paper's element-test fit of η from 8",
          "[app][scene][calibration]") {
  const CalibrationScene c = calibration("calibration_dr15");
  CHECK(c.lab_file.filename() == "triaxial_dr15.csv");
  CHECK(c.lab.axial_strain.size() == 49);
  CHECK(c.specimen == SpecimenType::element);
  CHECK(c.settings.mode == CalibrationMode::dissipated_work);
  CHECK(c.eta_start == 8.0);
  CHECK(c.settings.eta_min == 0.1);
  CHECK(c.settings.eta_max == 500.0);
  CHECK(c.compare_eta == std::vector<double>{2.5, 15.0});
  CHECK(c.compare_modes);
  CHECK(c.test.increments == 1000);
  CHECK(c.test.cell_pressure_Pa == Approx(1720.0));
  CHECK(c.test.axial_strain_max == c.lab.axial_strain.back());
  CHECK(c.settings.derivative_step == 1e-4);
  CHECK(c.settings.parameter_tolerance == 1e-8);
  CHECK(c.settings.work_tolerance == 0.0);
  // The element test's fit as it always was: from material.eta, central differences, 9-point scan.
  CHECK(c.fit_start == FitStart::material_eta);
  CHECK(c.settings.eta_start == 8.0);
  CHECK(c.settings.derivative == FitDerivative::central);
  CHECK(c.settings.scan_points == 9);
  CHECK(c.settings.scan_extra_eta == c.compare_eta);
  CHECK(c.material.friction_peak_rad == Approx(40.0 * kDegree));
  CHECK_FALSE(c.fitted_peak_friction);
}

TEST_CASE("calibration reader: calibration_dr15_mpm_2cm is the meshed specimen with the mpm defaults",
          "[app][scene][calibration]") {
  const CalibrationScene c = calibration("calibration_dr15_mpm_2cm");
  CHECK(c.specimen == SpecimenType::mpm);
  CHECK(c.mpm.cell_m == 0.02);
  CHECK(c.mpm.platens == PlatenFriction::rough);
  CHECK(c.mpm.shape_function == mpm::ShapeFunction::gimp);
  CHECK(c.mpm.courant == 0.9);
  CHECK(c.mpm.flip_fraction == 0.9);
  CHECK(c.mpm.particles_per_cell == 2);
  CHECK(c.mpm.cell_pressure_Pa == Approx(1720.0));
  CHECK(c.mpm.specimen.height_m == 0.15);
  CHECK_FALSE(c.compare_modes);
  CHECK(c.settings.derivative_step == 0.1);
  CHECK(c.settings.parameter_tolerance == 1e-4);
  CHECK(c.settings.work_tolerance == 2e-4);
  // The meshed fit's fewer runs: 3-point scan (plus compare_eta), from its crossing, secants.
  CHECK(c.fit_start == FitStart::scan);
  CHECK_FALSE(c.settings.eta_start.has_value());
  CHECK(c.settings.derivative == FitDerivative::secant);
  CHECK(c.settings.scan_points == 3);
  const CalibrationScene old_path =
      calibration("calibration_dr15_mpm_2cm", {"fit_start=material_eta", "derivative=central", "scan_points=9"});
  CHECK(old_path.settings.eta_start == 8.0);
  CHECK(old_path.settings.derivative == FitDerivative::central);
  CHECK(old_path.settings.scan_points == 9);
  CHECK(c.settings.scan == WorkScan::bounds);
  const CalibrationScene bracket = calibration("calibration_dr15_mpm_2cm", {"scan=bracket", "material.eta=60"});
  CHECK(bracket.settings.scan == WorkScan::bracket);
  CHECK(bracket.settings.bracket_start_eta == 60.0);  // material.eta, whatever fit_start says
  CHECK_FALSE(bracket.settings.eta_start.has_value());
  CHECK(calibration("calibration_dr15_mpm_2cm", {"specimen.platens=smooth", "specimen.shape_function=linear"})
            .mpm.platens == PlatenFriction::smooth);
  CHECK(calibration("calibration_dr15", {"mode=curve_least_squares"}).settings.mode ==
        CalibrationMode::curve_least_squares);
}

TEST_CASE("calibration reader: a bad key names itself and what it may be", "[app][scene][calibration]") {
  CHECK(calibration_error("calibration_dr15", "mode=least") ==
        "mode: 'least' is not allowed: must be one of: dissipated_work, curve_least_squares");
  CHECK(calibration_error("calibration_dr15", "eta_min=-1") ==
        "eta_min: = -1 is out of range: must be > 0 and ≤ 10000");
  CHECK(calibration_error("calibration_dr15", "derivative=forward") ==
        "derivative: 'forward' is not allowed: must be one of: central, secant");
  CHECK(calibration_error("calibration_dr15", "fit_start=middle") ==
        "fit_start: 'middle' is not allowed: must be one of: material_eta, scan");
  CHECK(calibration_error("calibration_dr15", "scan=all") ==
        "scan: 'all' is not allowed: must be one of: bounds, bracket");
  CHECK(scene_error([] {
          calibration("calibration_dr15", {"scan=bracket", "mode=curve_least_squares"});
        }) == "scan: 'bracket' brackets W_lab: it needs mode dissipated_work");
  CHECK(scene_error([] {
          calibration("calibration_dr15", {"scan=bracket", "scan_points=5"});
        }) == "scan_points: belongs to scan 'bounds' (the bracket widens as needed)");
  CHECK(calibration_error("calibration_dr15_mpm_2cm", "specimen.platens=sticky") ==
        "specimen.platens: 'sticky' is not allowed: must be one of: rough, smooth");
  CHECK(calibration_error("calibration_dr15_mpm_2cm", "specimen.shape_function=quad") ==
        "specimen.shape_function: 'quad' is not allowed: must be one of: gimp, linear");
  CHECK(calibration_error("calibration_dr15", "specimen.cell_m=0.01") ==
        "specimen.cell_m: unknown key for an element specimen (type, height_m, diameter_m; the MPM keys need \"type\": "
        "\"mpm\"); allowed keys: diameter_m, height_m, type");
  CHECK(calibration_error("calibration_dr15", "specimen.type=mpm") ==
        "increments: belongs to the element test; an mpm specimen (specimen.type = mpm) is resolved by its cell_m and "
        "time step, and strained by its platen_velocity_m_s");
}

TEST_CASE("integration_error reader: the shipped study and its bad keys", "[app][scene][integration_error]") {
  const IntegrationErrorScene s = integration_error();
  CHECK(s.study.increments == std::vector<int>{10, 20, 50, 100, 200, 500, 1000, 2000, 5000, 10000});
  CHECK(s.study.reference_increments == 100000);
  CHECK(s.study.axial_strain_max == 0.2);
  CHECK(s.study.cell_pressure_Pa == Approx(1720.0));
  CHECK(s.study.min_timing_s == 0.05);
  CHECK(s.maps.points_x == 21);
  CHECK(s.maps.points_y == 41);
  CHECK(s.maps.max_multiple == 10.0);
  CHECK(s.maps.reference_substeps == 2000);
  CHECK(s.maps.confining_Pa == s.study.cell_pressure_Pa);
  CHECK(s.material.softening_factor == 8.0);
  CHECK(scene_error([] { integration_error({"maps.points_x=1"}); }) ==
        "maps.points_x: = 1 is out of range: must be an integer in [2, 1000]");
  CHECK(scene_error([] { integration_error({"maps.colour=1"}); }) ==
        "maps.colour: unknown key for maps; allowed keys: max_trial_over_yield_strain, points_x, points_y, "
        "reference_substeps");
  CHECK(scene_error([] { integration_error({"increments=[10,2.5]"}); }) == "increments[1]: must be a whole number");
}

TEST_CASE("mpm reader: the wave column and its bad keys", "[app][scene][mpm]") {
  const MpmScene s = mpm_scene("mpm_wave_column");
  CHECK(s.body_names == std::vector<std::string>{"column"});
  CHECK(s.end_time_s == 0.02);
  CHECK(s.model.r_nodes_m.size() == 3);
  CHECK(s.model.z_nodes_m.size() == 101);
  CHECK(s.model.boundaries.inner == mpm::Fixity::roller);
  CHECK(s.model.boundaries.outer == mpm::Fixity::roller);
  CHECK(s.model.boundaries.bottom == mpm::Fixity::fixed);
  CHECK(s.model.boundaries.top == mpm::Fixity::free);
  CHECK(s.model.solver.shape_function == mpm::ShapeFunction::gimp);
  CHECK(s.model.solver.transfer == mpm::Transfer::musl);
  CHECK(s.output.probes.size() == 2);
  CHECK(s.output.field_times_s.size() == 11);
  CHECK(mpm_scene("mpm_wave_column", {"solver.transfer=musl_remapped"}).model.solver.transfer ==
        mpm::Transfer::musl_remapped);
  CHECK(mpm_scene("mpm_wave_column", {"boundaries.top=roller"}).model.boundaries.top == mpm::Fixity::roller);
  CHECK(scene_error([] { mpm_scene("mpm_wave_column", {"solver.transfer=xsl"}); }) ==
        "solver.transfer: 'xsl' is not allowed: must be one of: usl, musl, musl_remapped (did you mean 'usl'?)");
  CHECK(scene_error([] { mpm_scene("mpm_wave_column", {"boundaries.axis=free"}); }) ==
        "boundaries.axis: 'free' is not allowed: must be one of: roller, fixed");
  CHECK(scene_error([] { mpm_scene("mpm_wave_column", {"solver.shape_function=3"}); }) ==
        "solver.shape_function: must be one of: linear, gimp; got a number");
  CHECK(scene_error([] { mpm_scene("mpm_wave_column", {"boundaries.inner=free"}); }) ==
        "boundaries.inner: unknown key for boundaries (axis, outer, bottom, top); allowed keys: axis, bottom, "
        "drainage, outer, top");
}

TEST_CASE("mpm reader: the saturated Terzaghi column, and saturated keys where they do not belong",
          "[app][scene][mpm][saturated]") {
  const MpmScene s = mpm_scene("mpm_terzaghi_column");
  REQUIRE(s.model.bodies.size() == 1);
  REQUIRE(s.model.bodies[0].saturated);
  CHECK(s.model.bodies[0].saturated->porosity == 0.4);
  CHECK(s.model.bodies[0].saturated->permeability_m_s == 1e-3);
  CHECK(s.model.bodies[0].saturated->permeability_law == mpm::PermeabilityLaw::constant);
  CHECK(s.model.bodies[0].saturated->initial_excess_pressure_Pa == 0.0);  // hydrostatic by default
  CHECK(mpm_scene("mpm_terzaghi_column", {"bodies.0.initial_excess_pore_pressure_kPa=2"})
            .model.bodies[0]
            .saturated->initial_excess_pressure_Pa == 2000.0);
  CHECK(scene_error([] { mpm_scene("mpm_wave_column", {"bodies.0.initial_excess_pore_pressure_kPa=1"}); }) ==
        "bodies[0].initial_excess_pore_pressure_kPa: only with saturated: true");
  CHECK(s.model.bodies[0].density_kg_m3 == 1600.0);  // the dry density
  CHECK(s.model.fluid.bulk_modulus_Pa == 2.2e9);
  CHECK(s.model.fluid.density_kg_m3 == 1000.0);
  CHECK(s.model.drainage.bottom == mpm::Drainage::impermeable);
  CHECK(s.model.drainage.top == mpm::Drainage::drained);
  REQUIRE(s.model.pressures.size() == 1);
  CHECK(s.model.pressures[0].side == mpm::Side::top);
  CHECK(s.model.pressures[0].r_max_m == 0.1);
  CHECK(mpm_scene("mpm_terzaghi_column", {"fluid=null"}).model.fluid.bulk_modulus_Pa == 2.2e9);  // water by default
  CHECK(mpm_scene("mpm_terzaghi_column", {"bodies.0.permeability_law=kozeny_carman"})
            .model.bodies[0]
            .saturated->permeability_law == mpm::PermeabilityLaw::kozeny_carman);
  CHECK(mpm_scene("mpm_terzaghi_column", {"boundaries.drainage.bottom=drained"}).model.drainage.bottom ==
        mpm::Drainage::drained);
  CHECK(scene_error([] { mpm_scene("mpm_terzaghi_column", {"bodies.0.porosity=1"}); }) ==
        "bodies[0].porosity: = 1 is out of range: must be > 0 and < 1");
  CHECK(scene_error([] { mpm_scene("mpm_terzaghi_column", {"bodies.0.permeability_m_s=0"}); }) ==
        "bodies[0].permeability_m_s: = 0 is out of range: must be > 0 and ≤ 1 m/s");
  CHECK(scene_error([] { mpm_scene("mpm_terzaghi_column", {"bodies.0.porosity=null"}); }) ==
        "bodies[0].porosity: is required (> 0 and < 1)");
  CHECK(scene_error([] { mpm_scene("mpm_terzaghi_column", {"fluid.bulk_modulus_kPa=0"}); }) ==
        "fluid.bulk_modulus_kPa: = 0 is out of range: must be > 0 and ≤ 1e+08 kPa");
  CHECK(scene_error([] { mpm_scene("mpm_terzaghi_column", {"boundaries.drainage.top=impermeable"}); }) ==
        "boundaries.drainage.top: is impermeable but boundaries.top is free: hold the solid there too (roller or "
        "fixed), or make it drained");
  CHECK(scene_error([] { mpm_scene("mpm_terzaghi_column", {"boundaries.bottom=absorbing"}); }) ==
        "boundaries.bottom: a saturated body takes no absorbing sides");
  CHECK(scene_error([] {
          mpm_scene("mpm_terzaghi_column", {"surface_pressures.0.z_min_m=0"});
        }).rfind("surface_pressures[0].z_min_m: unknown key for a top pressure", 0) == 0);
  // A dry scene carries none of them, and its echo gains none.
  CHECK(scene_error([] { mpm_scene("mpm_terzaghi_column", {"bodies.0.saturated=false"}); }) ==
        "bodies[0].porosity: only with saturated: true");
  CHECK(scene_error([] { mpm_scene("mpm_wave_column", {R"(fluid={"density_kg_m3": 1000})"}); }) ==
        "fluid: only with a saturated body (bodies[i].saturated: true)");
  CHECK(scene_error([] { mpm_scene("mpm_wave_column", {R"(boundaries.drainage={"top": "drained"})"}); }) ==
        "boundaries.drainage: only with a saturated body (bodies[i].saturated: true)");
  ShippedScene dry("mpm_wave_column");
  (void)read_mpm_scene(dry.reader());
  CHECK_FALSE(dry.echo().contains("fluid"));
  CHECK_FALSE(dry.echo()["bodies"][0].contains("saturated"));
  CHECK_FALSE(dry.echo()["boundaries"].contains("drainage"));
}

TEST_CASE("ffp reader: the reference drop and its bad keys", "[app][scene][ffp]") {
  const FfpScene s = ffp_scene("ffp_reference", PenetrometerKind::ffp);
  CHECK(s.kind == PenetrometerKind::ffp);
  CHECK(s.end_time_s == 0.15);
  CHECK(s.model.mass_kg == 7.71);
  CHECK(s.model.velocity_m_s == -5.6);
  CHECK_FALSE(s.model.prescribed);
  CHECK_FALSE(s.model.deformable);
  CHECK(s.model.force == mpm::RigidBodyForce::contact_impulse);
  CHECK(s.model.contact.friction == Approx(std::tan(20.0 * kDegree)));
  CHECK(s.model.mesh.min_cell_m == 0.01);
  CHECK(s.model.solver.transfer == mpm::Transfer::usl);
  CHECK(s.model.solver.shape_function == mpm::ShapeFunction::gimp);
  CHECK(s.model.pic_blend == mpm::PicBlend::per_soil_step);
  CHECK(s.output.history_interval_s == 2e-4);
  CHECK(ffp_scene("ffp_reference", PenetrometerKind::ffp, {"ffp.rigid_body_force=soil_internal_force"}).model.force ==
        mpm::RigidBodyForce::soil_internal_force);
  CHECK(ffp_scene("ffp_reference", PenetrometerKind::ffp, {"solver.pic_blend=per_step"}).model.pic_blend ==
        mpm::PicBlend::per_step);
  CHECK(ffp_scene("ffp_steel", PenetrometerKind::ffp).model.deformable.has_value());
  const FfpScene cpt = ffp_scene("cpt_reference", PenetrometerKind::cpt);
  CHECK(cpt.model.prescribed);
  CHECK(cpt.model.velocity_m_s < 0.0);
  CHECK(scene_error([] { ffp_scene("ffp_reference", PenetrometerKind::ffp, {"solver.pic_blend=sometimes"}); }) ==
        "solver.pic_blend: 'sometimes' is not allowed: must be one of: per_soil_step, per_step, per_second");
  CHECK(scene_error([] { ffp_scene("ffp_reference", PenetrometerKind::ffp, {"ffp.mass_kg=0"}); }) ==
        "ffp.mass_kg: = 0 is out of range: must be > 0 and ≤ 1e+06 kg");
  CHECK(scene_error([] { ffp_scene("ffp_reference", PenetrometerKind::ffp, {"ffp.rigid_body_force=contact"}); }) ==
        "ffp.rigid_body_force: 'contact' is not allowed: must be one of: contact_impulse, soil_internal_force (did you "
        "mean 'contact_impulse'?)");
  CHECK(scene_error([] { ffp_scene("ffp_steel", PenetrometerKind::ffp, {"ffp.rigid_body_force=contact_impulse"}); }) ==
        "ffp.rigid_body_force: applies to a rigid penetrometer only (this one is deformable)");
}

TEST_CASE("ffp reader: the mesh's offsets lie within a cell and the body spans three cells", "[app][scene][ffp]") {
  // The reader is the one place of these ranges (mpm's ffp_grid_layout only asserts them).
  CHECK(scene_error([] { ffp_scene("ffp_reference", PenetrometerKind::ffp, {"mesh.tip_offset_cells=1"}); }) ==
        "mesh.tip_offset_cells: = 1 is out of range: must be ≥ 0 and < 1 cells");
  CHECK(scene_error([] { ffp_scene("ffp_reference", PenetrometerKind::ffp, {"mesh.edge_offset_cells=1"}); }) ==
        "mesh.edge_offset_cells: = 1 is out of range: must be ≥ 0 and < 1 cells");
  CHECK(scene_error([] {
          ffp_scene("ffp_reference", PenetrometerKind::ffp, {"ffp.body_length_m=0", "mesh.min_cell_m=0.03"});
        }) == "mesh.min_cell_m: must be at most a third of the penetrometer's length (its cone and ffp.body_length_m)");
  CHECK(ffp_scene("ffp_reference", PenetrometerKind::ffp, {"ffp.body_length_m=0", "mesh.min_cell_m=0.02"})
            .model.mesh.min_cell_m == 0.02);  // the cone alone, 7.6 cm, spans three 2 cm cells
}

TEST_CASE("record reader: the reference record and its bad keys", "[app][scene][record]") {
  const RecordScene r = record_scene();
  CHECK(r.record_csv.filename() == "ffp_reference_synthetic.csv");
  CHECK(r.settings.mass_kg == 7.71);
  CHECK(r.settings.medium == DropMedium::air);
  CHECK(r.settings.impact_velocity_m_s == 5.6);
  CHECK(r.settings.impact_time_s == 0.0);
  CHECK(r.settings.tip.base_radius_m == 0.04375);
  CHECK_FALSE(r.settings.q_sbc_on_mantle);
  REQUIRE(r.settings.rate_laws.size() == 3);
  CHECK(rate_law_name(r.settings.rate_laws[1].law) == "brilli");
  CHECK(r.settings.rate_laws[1].k == 0.31);
  CHECK_FALSE(r.sensor_range);
  const RecordScene water = record_scene({"medium=water", "ffp.volume_m3=0.003"});
  CHECK(water.settings.medium == DropMedium::water);
  CHECK(water.settings.fluid_density_kg_m3 == 1020.0);
  CHECK(scene_error([] { record_scene({"medium=oil"}); }) ==
        "medium: 'oil' is not allowed: must be one of: air, water (did you mean 'air'?)");
  CHECK(scene_error([] { record_scene({"impact_threshold_g=-2"}); }) ==
        "impact_threshold_g: detects the impact; with impact_time_s given there is nothing to detect");
}

TEST_CASE("inverse reader: the reference fit and its bad keys", "[app][scene][inverse]") {
  const InverseScene s = inverse_scene();
  CHECK(s.forward_scene.filename() == "ffp_reference.json");
  CHECK(s.forward_overrides == std::vector<std::string>{"mesh.min_cell_m=0.02", "end_time_s=0.1"});
  REQUIRE(s.parameters.size() == 2);
  CHECK(s.parameters[0].name == "material.phi_peak_deg");
  CHECK(s.parameters[0].initial == 35.0);
  CHECK(s.parameters[0].lower == 30.0);
  CHECK(s.parameters[0].upper == 50.0);
  CHECK(s.parameters[1].name == "material.E_kPa");
  REQUIRE(s.record);
  CHECK(s.record->settings.impact_velocity_m_s == 5.6);
  CHECK(s.profile);
  CHECK(s.profile_points == 40);
  CHECK(s.fit.max_iterations == 15);
  CHECK(scene_error([] { inverse_scene({"max_iterations=0"}); }) ==
        "max_iterations: = 0 is out of range: must be an integer in [1, 200]");
  CHECK(scene_error([] { inverse_scene({"record.medium=oil"}); }) ==
        "record.medium: 'oil' is not allowed: must be one of: air, water (did you mean 'air'?)");
  CHECK(scene_error([] { inverse_scene({"parameters.0.key=material.nu"}); }) ==
        "parameters[0].key: 'material.nu' cannot be fitted: must be one of material.phi_peak_deg, material.E_kPa, "
        "material.eta, contact.delta_deg, material.rate_dependence.alpha_phi");
}

// A run's summary.json echoes its scene with every default filled in, so that the run can be
// repeated from it: a key the reader only accepts in some configurations (solver.subcycle with a
// deformable body, scan_points with the bounds scan) must then not be echoed in the others.
TEST_CASE("every shipped scene's echo is itself a valid scene with the same echo", "[app][scene]") {
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(ShippedScene::dir())) {
    if (entry.path().extension() != ".json") continue;
    const json scene = load_scene_file(entry.path().string());
    json echo = json::object();
    (void)make_job(scene, ShippedScene::dir(), echo);
    json echo_again = json::object();
    INFO(entry.path().filename().string());
    REQUIRE_NOTHROW(make_job(echo, ShippedScene::dir(), echo_again));
    CHECK(echo_again == echo);
    ++scenes;
  }
  CHECK(scenes >= 30);
}
