// Drives one uniaxial material point through a strain history: for each imposed strain,
// evaluate from the committed state, commit, record (the `brb material` command and the
// material checks). A strain increment whose evaluation fails (local Newton of a collapsed
// 3D law not converged, or non-finite numbers) is retried in 2, 4, 8, ... equal substeps.
#pragma once

#include "brb/material/fiber_condensation.hpp"
#include "brb/material/mortar_damage.hpp"
#include "brb/material/steel_damage_plasticity_3d.hpp"
#include "brb/material/steel_uniaxial.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <span>
#include <stdexcept>
#include <utility>
#include <variant>
#include <vector>

namespace brb::analysis {

/// The 3D laws collapsed to a beam fiber (sigma_22 = sigma_33 = all shears = 0) by local Newton.
using CollapsedSteel = material::FiberCondensation<material::SteelDamagePlasticity3D>;
using CollapsedMortar = material::FiberCondensation<material::MortarDamage3D>;

/// A uniaxial material point: each law in its two exact evaluations (closed form, collapsed 3D).
using UniaxialMaterialPoint = std::variant<material::SteelUniaxial, CollapsedSteel,
                                           material::MortarUniaxial, CollapsedMortar>;

/// The committed response at one imposed strain.
struct MaterialPathPoint {
  double strain = 0.0;  ///< imposed axial strain (-)
  double stress = 0.0;  ///< axial stress (MPa)
  double tangent = 0.0; ///< d stress / d strain (MPa): consistent (condensed) tangent
  double damage = 0.0;  ///< scalar damage d in [0, 1)
};

struct SubsteppingPolicy {
  /// Largest number of equal substeps tried for one increment (1, 2, 4, ... up to this).
  int max_substeps = 1024;
};

struct MaterialPathResult {
  std::vector<MaterialPathPoint> points; ///< one per imposed strain
  std::size_t substepped_increments = 0; ///< increments that needed more than one substep
  int most_substeps = 1;                 ///< largest number of substeps any increment used
};

/// The increment to strain `strains[row]` failed even with the largest number of substeps.
class MaterialPathFailure : public std::runtime_error {
public:
  MaterialPathFailure(std::size_t row, double strain, int substeps);
  std::size_t row() const { return row_; } ///< 0-based index in the history
  double strain() const { return strain_; }
  int substeps() const { return substeps_; }

private:
  std::size_t row_;
  double strain_;
  int substeps_;
};

/// Drives `point` from its initial (virgin) state at zero strain through `strains`.
/// Throws MaterialPathFailure when an increment cannot be evaluated, and
/// std::invalid_argument when policy.max_substeps < 1.
MaterialPathResult drive_strain_path(const UniaxialMaterialPoint& point,
                                     std::span<const double> strains,
                                     const SubsteppingPolicy& policy = {});

/// The same for any point type with State, initial_state() and either
///  - evaluate(const State&, double) -> {stress, tangent, state} with state.damage (closed-form
///    uniaxial laws), or
///  - evaluate(const State&, GivenVector) -> {stress[0], tangent(0, 0), state, converged} with
///    state.material.damage (material::FiberCondensation).
template <class Point>
MaterialPathResult drive_strain_path_of(const Point& point, std::span<const double> strains,
                                        const SubsteppingPolicy& policy = {});

// ---------------------------------------------------------------------------------------
// Implementation

namespace detail {

/// FiberCondensation takes the given strains as a vector; the closed forms take a number.
template <class Point> constexpr bool kTakesStrainVector = requires {
  typename Point::GivenVector;
};

/// One accepted evaluation of a point: the response and the state to commit.
template <class State> struct Trial {
  MaterialPathPoint response;
  State state;
};

/// Evaluates `point` at `strain` from `committed`; nothing when the evaluation is unusable
/// (local Newton not converged, or non-finite stress, tangent or damage).
template <class Point>
std::optional<Trial<typename Point::State>>
try_evaluate(const Point& point, const typename Point::State& committed, double strain) {
  MaterialPathPoint response{.strain = strain};
  bool converged = true;
  auto evaluation = [&] {
    if constexpr (kTakesStrainVector<Point>) {
      typename Point::GivenVector given;
      given[0] = strain;
      return point.evaluate(committed, given);
    } else {
      return point.evaluate(committed, strain);
    }
  }();
  if constexpr (kTakesStrainVector<Point>) {
    converged = evaluation.converged;
    response.stress = evaluation.stress[0];
    response.tangent = evaluation.tangent(0, 0);
    response.damage = evaluation.state.material.damage;
  } else {
    response.stress = evaluation.stress;
    response.tangent = evaluation.tangent;
    response.damage = evaluation.state.damage;
  }
  const bool finite = std::isfinite(response.stress) && std::isfinite(response.tangent) &&
                      std::isfinite(response.damage);
  if (!converged || !finite)
    return std::nullopt;
  return Trial<typename Point::State>{response, std::move(evaluation.state)};
}

/// The increment from `start_strain` (state `committed`) to `end_strain` in `substeps` equal
/// parts, each evaluated from the state accepted at the previous one.
template <class Point>
std::optional<Trial<typename Point::State>>
try_increment(const Point& point, const typename Point::State& committed, double start_strain,
              double end_strain, int substeps) {
  std::optional<Trial<typename Point::State>> trial;
  const typename Point::State* state = &committed;
  for (int substep = 1; substep <= substeps; ++substep) {
    const double strain =
        substep == substeps
            ? end_strain
            : start_strain + (end_strain - start_strain) * substep / static_cast<double>(substeps);
    auto next = try_evaluate(point, *state, strain);
    if (!next)
      return std::nullopt;
    trial = std::move(next);
    state = &trial->state;
  }
  return trial;
}

} // namespace detail

template <class Point>
MaterialPathResult drive_strain_path_of(const Point& point, std::span<const double> strains,
                                        const SubsteppingPolicy& policy) {
  if (policy.max_substeps < 1) {
    throw std::invalid_argument("SubsteppingPolicy: max_substeps must be >= 1");
  }
  MaterialPathResult result;
  result.points.reserve(strains.size());
  typename Point::State committed = point.initial_state();
  double committed_strain = 0.0;
  for (std::size_t row = 0; row < strains.size(); ++row) {
    const double strain = strains[row];
    std::optional<detail::Trial<typename Point::State>> accepted;
    int substeps = 1;
    for (; substeps <= policy.max_substeps; substeps *= 2) {
      accepted = detail::try_increment(point, committed, committed_strain, strain, substeps);
      if (accepted)
        break;
    }
    if (!accepted)
      throw MaterialPathFailure(row, strain, policy.max_substeps);
    if (substeps > 1) {
      ++result.substepped_increments;
      result.most_substeps = std::max(result.most_substeps, substeps);
    }
    result.points.push_back(accepted->response);
    committed = std::move(accepted->state);
    committed_strain = strain;
  }
  return result;
}

} // namespace brb::analysis
