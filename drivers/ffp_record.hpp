#pragma once
/// A free-fall penetrometer's deceleration record, interpreted as FFP
/// practitioners do: the kinematics integrated from impact, the dynamic
/// bearing pressure q_dyn on the projected and the mantle contact area, and
/// the quasi-static bearing q_sbc through a strain-rate factor. Pure math: the
/// `record` kind reads a measured file into it, and every `ffp` run feeds its
/// own history through the same functions, so a simulation and a measurement
/// are read the same way.
///
/// Sign conventions: depth and velocity + down; the net deceleration
/// (R − M g)/(M g) + while it slows a downward motion (the `ffp` history's
/// deceleration_g), so free fall reads −1 and rest on the soil reads 0.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ffp {

/// A record that cannot be interpreted (bad samples, no impact): the message
/// names the column and the data row (1 = the first row after the header).
class RecordError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Strain-rate factors f_SR(v) that turn q_dyn into q_sbc = q_dyn / f_SR.
enum class RateLaw : std::uint8_t { logarithmic, brilli, inverse_hyperbolic_sine };
using RateLawName = std::pair<RateLaw, std::string_view>;
/// The laws' names: their keys under the scene's rate_laws and their q_sbc_<name>_kPa columns.
inline constexpr auto kRateLawNames = std::to_array<RateLawName>(
    {{RateLaw::logarithmic, "log"}, {RateLaw::brilli, "brilli"}, {RateLaw::inverse_hyperbolic_sine, "asinh"}});
inline std::string_view rate_law_name(RateLaw law) {
  return std::ranges::find(kRateLawNames, law, &RateLawName::first)->second;
}

struct RateCorrection {
  RateLaw law = RateLaw::logarithmic;
  double k = 0.1;
};

/// f_SR at penetration velocity v (+ down); 1 at or below the reference
/// velocity, where the laws stop describing a rate effect (the logarithm would
/// fall below 1 and then below 0 as the penetrometer comes to rest).
double strain_rate_factor(const RateCorrection& correction, double velocity_m_s, double reference_velocity_m_s,
                          double impact_velocity_m_s);

/// The tip's contact areas at a penetration depth, from the straight cone
/// r(z) = R·min(z, h_c)/h_c (the edge fillet left out, as in the practitioners'
/// formulas). A flat tip (h_c = 0) touches with its whole base at once.
struct TipAreas {
  double base_radius_m = 0.04375;
  double cone_height_m = 0.07578;
  double projected_m2(double depth_m) const;  ///< π r(z)²
  double mantle_m2(double depth_m) const;     ///< the cone's lateral area up to r(z) (a flat tip: π R²)
};

enum class DropMedium : std::uint8_t { air, water };
using DropMediumName = std::pair<DropMedium, std::string_view>;
/// The scene's names of DropMedium, in the order messages list them.
inline constexpr auto kDropMediumNames =
    std::to_array<DropMediumName>({{DropMedium::air, "air"}, {DropMedium::water, "water"}});
inline std::string to_string(DropMedium medium) {
  return std::string(std::ranges::find(kDropMediumNames, medium, &DropMediumName::first)->second);
}

struct RecordSettings {
  double mass_kg = 7.71;
  double gravity_m_s2 = 9.81;
  TipAreas tip;
  std::optional<double> impact_velocity_m_s;  ///< + down; absent: integrated from rest at the record's first sample
  std::optional<double> impact_time_s;        ///< absent: detected by impact_threshold_g
  double impact_threshold_g = 1.0;            ///< the pulse that first exceeds this net deceleration is the impact
  DropMedium medium = DropMedium::air;
  double fluid_density_kg_m3 = 1.2;      ///< air 1.2, sea water 1020 (BlueDrop's default)
  double drag_coefficient = 0.0;         ///< on the frontal area π R²; 0 leaves drag out
  double volume_m3 = 0.0;                ///< the penetrometer's, for buoyancy in water
  double reference_velocity_m_s = 0.02;  ///< v_ref of the rate laws: the standard CPT rate
  bool q_sbc_on_mantle = false;          ///< q_sbc from q_dyn on the mantle area (default: projected)
  std::vector<RateCorrection> rate_laws;
};

struct InterpretedRecord {
  std::size_t impact_index = 0;  ///< sample of the impact in the input
  double impact_time_s = 0.0;
  double impact_velocity_m_s = 0.0;         ///< + down
  bool impact_detected = true;              ///< false: impact_time_s was given
  bool impact_velocity_integrated = false;  ///< true: from rest at the first sample (release)
  /// One row per sample after the impact (the first has a contact area > 0).
  std::vector<double> time_s, penetration_m, velocity_m_s, deceleration_g;
  std::vector<double> q_dyn_projected_kPa, q_dyn_mantle_kPa;
  std::vector<std::vector<double>> q_sbc_kPa;  ///< per rate law, in settings.rate_laws' order
  double peak_deceleration_g = 0.0, time_of_peak_s = 0.0, depth_of_peak_m = 0.0;
  double max_penetration_m = 0.0, final_penetration_m = 0.0;
};

/// Checks a channel against time: time strictly increasing, no gap longer than
/// `max_gap_ratio` times the median sampling interval, and no saturation. With
/// `full_scale` a sample at or beyond ±full_scale is saturated; without it, a
/// flat top (at least 5 equal samples at the channel's maximum with lower
/// samples on both sides) is. Throws RecordError.
void check_record_channel(const std::vector<double>& time_s, const std::vector<double>& values, std::string_view column,
                          std::optional<double> full_scale, double max_gap_ratio = 5.0);

/// The sample where the impact pulse starts: the start of the rise that first
/// exceeds `threshold_g`. Throws RecordError when no sample does.
std::size_t detect_impact(const std::vector<double>& deceleration_g, double threshold_g);

/// Integrates the record from its impact (given, or detected) and derives q_dyn and q_sbc. Throws
/// RecordError when no impact is found or settings.impact_time_s lies outside the record (or on its
/// last sample). Whether the result can be a penetrometer's impact is record_plausibility.hpp's to say.
InterpretedRecord interpret_record(const std::vector<double>& time_s, const std::vector<double>& deceleration_g,
                                   const RecordSettings& settings);

}  // namespace ffp
