#pragma once
/// The scene of a measured FFP drop (`record` kind, and the record an
/// `inverse` fit matches): the file, how its channel reads, the penetrometer
/// and the interpretation's settings. Reading only; record_job runs it.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "drivers/ffp_record.hpp"
#include "drivers/scene/scene_reader.hpp"

namespace ffp {

struct RecordScene {
  std::filesystem::path record_csv;  ///< resolved against the scene's folder
  RecordSettings settings;
  std::optional<double> sensor_range;  ///< full scale, in the channel's unit
};

/// Reads the record's keys (`ffp keys record`, each declared where it is read).
/// Does not finish() the reader.
RecordScene read_record_scene(SceneReader& scene, const std::filesystem::path& scene_dir);

/// A record's samples, as net deceleration (+ slowing, g) against time.
struct RecordSamples {
  std::vector<double> time_s, deceleration_g;
  std::optional<std::vector<double>> pore_pressure_kPa;
  std::string channel;  ///< the column the deceleration came from
};

/// Reads and checks the file: time_s and exactly one of deceleration_g (net,
/// + while slowing) or acceleration_m_s2 (the accelerometer's reading along
/// the axis, sky positive: +g at rest, 0 in free fall; gravity is subtracted
/// here, d = a/g − 1), optionally pore_pressure_kPa. Throws SceneError naming
/// the file, the row and the column.
RecordSamples load_record(const RecordScene& scene);

}  // namespace ffp
