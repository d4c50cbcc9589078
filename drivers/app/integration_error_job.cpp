/// The `integration_error` scene kind run: error of the constitutive integration
/// against its run time (drivers/integration_study.hpp), as CSV tables and
/// log-log / heat-map PNGs. The keys are read in integration_error_scene.hpp.
#include <cmath>
#include <filesystem>
#include <memory>
#include <ostream>

#include "drivers/app/integration_error_scene.hpp"
#include "drivers/app/job.hpp"
#include "drivers/app/kinds.hpp"
#include "drivers/integration_study.hpp"
#include "drivers/output/csv_writer.hpp"
#include "drivers/output/interrupt.hpp"
#include "models/mohr_coulomb.hpp"
#include "reports/heatmap.hpp"
#include "reports/plot.hpp"

namespace ffp {

namespace {

namespace fs = std::filesystem;

MohrCoulombParameters peak_mohr_coulomb(const StrainSofteningParameters& s) {
  MohrCoulombParameters p;
  p.elastic = s.elastic;
  p.friction_angle_rad = s.friction_peak_rad;
  p.dilatancy_angle_rad = s.dilatancy_peak_rad;
  p.cohesion_Pa = s.cohesion_peak_Pa;
  return p;
}

class IntegrationErrorJob : public Job {
 public:
  IntegrationErrorJob(StrainSofteningParameters material, TriaxialErrorStudy study, IsoErrorMapStudy maps)
      : material_(std::move(material)), study_(std::move(study)), maps_(std::move(maps)) {}

  void describe(std::ostream& out) const override {
    out << "integration_error: drained triaxial with";
    for (int n : study_.increments) out << " " << n;
    out << " increments against " << study_.reference_increments << "; iso-error maps " << maps_.points_x << "×"
        << maps_.points_y << " with " << maps_.reference_substeps << " reference substeps\n";
  }

  void run(RunContext& context) override {
    const fs::path plots = context.out_dir / "plots";
    fs::create_directories(plots);
    const std::vector<std::pair<std::string, PointLaw>> laws = {
        {"ssmc", StrainSofteningMohrCoulomb(material_)}, {"mohr_coulomb", MohrCoulomb(peak_mohr_coulomb(material_))}};
    const std::vector<std::string> titles = {"SSMC", "MC"};  // gnuplot reads '_' as a subscript

    // law: 0 ssmc, 1 mohr_coulomb. Errors relative (see drivers/integration_study.hpp).
    CsvTable table({"law", "increments", "wall_time_s", "q_error_end", "volumetric_strain_error_end", "q_error_path",
                    "volumetric_strain_error_path", "peak_q_error", "peak_q_kPa"});
    std::vector<Series> series;
    long steps = 0;
    for (std::size_t l = 0; l < laws.size(); ++l) {
      TriaxialErrorStudy study = study_;
      study.law = laws[l].second;
      const TriaxialErrorResult result = run_triaxial_error_study(study, [&](const std::string& stage) {
        throw_if_interrupted();
        if (context.show_progress)
          std::fprintf(stderr, "integration_error: %s triaxial, %s\n", laws[l].first.c_str(), stage.c_str());
      });
      steps += result.total_increments;
      Series q{{}, {}, titles[l] + ": q at the end", "linespoints"};
      Series ev{{}, {}, titles[l] + ": ε_v at the end", "linespoints dashtype 2"};
      Series q_path{{}, {}, titles[l] + ": q, max over the path", "linespoints dashtype 3"};
      json rows = json::array();
      for (const auto& row : result.rows) {
        table.add_row({static_cast<double>(l), static_cast<double>(row.increments), row.wall_time_s, row.q_error,
                       row.volumetric_error, row.q_error_path, row.volumetric_error_path, row.peak_q_error,
                       row.peak_q_kPa});
        // Exact results (the perfectly plastic return) have zero error: shown at 1e-17.
        q.x.push_back(row.wall_time_s);
        q.y.push_back(std::max(row.q_error, 1e-17));
        ev.x.push_back(row.wall_time_s);
        ev.y.push_back(std::max(row.volumetric_error, 1e-17));
        q_path.x.push_back(row.wall_time_s);
        q_path.y.push_back(std::max(row.q_error_path, 1e-17));
        rows.push_back({{"increments", row.increments},
                        {"wall_time_s", row.wall_time_s},
                        {"q_error_end", row.q_error},
                        {"volumetric_strain_error_end", row.volumetric_error},
                        {"q_error_path", row.q_error_path},
                        {"volumetric_strain_error_path", row.volumetric_error_path}});
      }
      series.push_back(q);
      series.push_back(ev);
      series.push_back(q_path);
      json& s = context.summary[laws[l].first + "_triaxial"];
      s["reference_increments"] = study.reference_increments;
      s["reference_wall_time_s"] = result.reference_wall_time_s;
      s["reference_peak_q_kPa"] = result.reference_peak_q_kPa;
      s["reference_final_volumetric_strain"] = result.reference_final_volumetric_strain;
      s["runs"] = rows;
    }
    table.write(context.out_dir / "triaxial_error.csv");
    Plot plot{"Drained triaxial to ε_a = " + format(100 * study_.axial_strain_max) + " %: error against wall time",
              "wall time of one run (s)",
              "relative error against the reference",
              series,
              true,
              true};
    plot.key_position = "top right";
    write_png(plot, plots / "error_vs_wall_time.png");

    json& map_summary = context.summary["iso_error_maps"];
    for (const auto& [name, law] : laws) {
      for (const MapStartName& entry : kMapStartNames) {
        const MapStart start = entry.first;
        throw_if_interrupted();
        IsoErrorMapStudy m = maps_;
        m.law = law;
        m.start = start;
        const IsoErrorMap map = run_iso_error_map(m);
        steps += map.updates;
        const std::string tag = name + "_" + to_string(start);
        CsvTable grid({"x_over_yield_strain", "y_over_yield_strain", "error"});
        double worst = 0.0;
        for (std::size_t j = 0; j < map.y.size(); ++j)
          for (std::size_t i = 0; i < map.x.size(); ++i) {
            const double e = map.error[j * map.x.size() + i];
            grid.add_row({map.x[i], map.y[j], e});
            worst = std::max(worst, e);
          }
        grid.write(context.out_dir / ("iso_error_" + tag + ".csv"));
        map_summary[tag] = {{"max_error", worst}, {"yield_strain", map.yield_strain}};
        HeatMap heat;
        heat.title = name + ", one increment from the " + to_string(start) + " against " +
                     std::to_string(m.reference_substeps) + " substeps";
        heat.x_label = "Δε along triaxial compression / ε_y";
        heat.y_label = "Δε along the Lode direction / ε_y";
        heat.value_label = "|σ(1 step) − σ(substeps)| / |σ plane start|";
        heat.x = map.x;
        heat.y = map.y;
        heat.values = map.error;
        heat.contour_levels = {1e-4, 1e-3, 1e-2, 1e-1, 1.0};
        write_heatmap_png(heat, plots / ("iso_error_" + tag + ".png"));
      }
    }
    context.steps = steps;
  }

 private:
  static std::string format(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return buffer;
  }

  StrainSofteningParameters material_;
  TriaxialErrorStudy study_;
  IsoErrorMapStudy maps_;
};

}  // namespace

std::unique_ptr<Job> make_integration_error_job(SceneReader& scene, const fs::path&) {
  IntegrationErrorScene s = read_integration_error_scene(scene);
  return std::make_unique<IntegrationErrorJob>(std::move(s.material), std::move(s.study), std::move(s.maps));
}

}  // namespace ffp
