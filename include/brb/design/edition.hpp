// The editions of ANSI/AISC 341 a BRB check can follow, and the limits that are parameters of
// the check (AISC341_NOTES.md). Every limit says where its value comes from.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace brb::design {

enum class Edition { aisc341_05, aisc341_10, aisc341_16, aisc341_22 };

/// "341-05", "341-10", "341-16", "341-22".
std::string to_string(Edition edition);
/// The edition named `name` ("341-16", ...), or nothing for an unknown name.
std::optional<Edition> edition_from_string(std::string_view name);
/// The names accepted by edition_from_string, in order.
std::vector<std::string> edition_names();

/// The limits of the qualification test and of the brace kinematics an edition sets.
struct EditionParameters {
  Edition edition = Edition::aisc341_16;
  /// Largest Pmax / Tmax of a cycle beyond Delta_by (acceptance criterion K3.8 d).
  double beta_limit = 1.3;
  std::string beta_limit_source;
  /// Tmax and Pmax of every cycle beyond Delta_by are at least this times Pysc (K3.8 c).
  double minimum_strength_ratio = 1.0;
  /// Cumulative inelastic axial deformation the brace test must reach (K3.4c step 6), in
  /// multiples of Delta_by.
  double cumulative_inelastic_target = 200.0;
  /// Delta_bm is computed from a design story drift not less than this times the story height.
  double minimum_drift_ratio = 0.01;
  /// beta and omega come from the cycles up to this multiple of Delta_bm (F4.2a: the
  /// deformation corresponding to 2.0 times the design story drift).
  double adjustment_range = 2.0;
  std::string source; ///< where the sequence and the other limits come from
};

/// The parameters of `edition`.
EditionParameters edition_parameters(Edition edition);

} // namespace brb::design
