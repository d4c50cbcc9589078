#pragma once
/// A resolved scene's identity: the same 16 hex digits on every machine, build
/// and run for the same scene, different ones for a scene that would run
/// differently. A sweep stores it with each case so that a finished result is
/// reused, or collected, only for the scene it ran.
///
/// FNV-1a, 64 bit (Fowler, Noll & Vo; offset basis 14695981039346656037,
/// prime 1099511628211): its value is fixed by its definition, unlike
/// std::hash, which may change between compilers and library versions. It
/// guards against honest mistakes (a folder re-emitted with other values, a
/// hand-edited case), not against an adversary: for n cases the chance of any
/// two different scenes colliding is about n²/2⁶⁵, 3·10⁻¹² for a million.
#include <cstdint>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace ffp {

inline constexpr std::uint64_t kFnv1aOffsetBasis = 14695981039346656037ull;

/// FNV-1a over `bytes`, continuing from `hash` (the offset basis to start).
std::uint64_t fnv1a_64(std::string_view bytes, std::uint64_t hash = kFnv1aOffsetBasis);

/// A hash as 16 lower-case hex digits.
std::string hex_digits(std::uint64_t hash);

/// The resolved scene (the echo, defaults filled in) as the hash sees it: the
/// description left out (prose, it changes no result) and every number a
/// double, so that 2500 and 2500.0 are one scene.
nlohmann::json canonical_scene(const nlohmann::json& echo);

/// hex_digits(fnv1a_64(canonical_scene(echo).dump())): the dump is canonical
/// because nlohmann's objects keep their keys sorted and it writes a double
/// with the shortest digits that read back to the same value.
std::string scene_hash(const nlohmann::json& echo);

/// Where two resolved scenes differ, for a message.
struct SceneDifference {
  std::string key;         ///< the first key that differs, as scenes write it ("material.E_kPa"); "" if none
  std::string before;      ///< its value in the first scene as JSON, "none" if absent there
  std::string after;       ///< the same in the second
  std::size_t others = 0;  ///< how many more keys differ

  /// "material.E_kPa = 1000.0 where `other` has 50000.0", with " (and N more keys)" when more differ.
  std::string text(std::string_view other) const;
};

/// The keys where `before` and `after` (canonical_scene of each) differ.
SceneDifference first_difference(const nlohmann::json& before, const nlohmann::json& after);

}  // namespace ffp
