// Collapse of any 3D law to the stress state of a beam fiber (DESIGN.md section 3):
// the given strains are eps_11 (and, with shears, gamma_12 and gamma_13); the other
// strains are solved by a local Newton so that their conjugate stresses vanish
// (sigma_22 = sigma_33 = sigma_23 = 0, and sigma_12 = sigma_13 = 0 without shears).
// The returned tangent is statically condensed: C_gg - C_gf C_ff^-1 C_fg.
//
// Law requirements (no virtual calls): types State and Response{stress, tangent, state},
// evaluate(const State&, const Vector6&) const, stress_scale() const.
//
// Damage laws of the form sigma = (1 - d) sigma_bar(eps) also return effective_stress and
// effective_tangent. For them the local Newton solves sigma_bar_f = 0 instead of
// sigma_f = 0 (the same condition while d < 1): the nominal residual admits spurious
// solutions, since an iterate with a large trial strain can drive d to 1 and make every
// nominal stress vanish, and its Jacobian degenerates as d -> 1.
#pragma once

#include "brb/material/tensor6.hpp"

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <utility>

namespace brb::material {

/// Fiber stress states. Voigt indices of the given strains, in the order the fiber uses.
enum class FiberStressState { uniaxial, uniaxial_with_shears };

template <FiberStressState kind> struct FiberComponents;
template <> struct FiberComponents<FiberStressState::uniaxial> {
  static constexpr int given = 1;
  static constexpr std::array<int, 1> given_index{0};
  static constexpr std::array<int, 5> free_index{1, 2, 3, 4, 5};
};
template <> struct FiberComponents<FiberStressState::uniaxial_with_shears> {
  static constexpr int given = 3;
  /// eps_11, gamma_12, gamma_13 (Voigt order 11, 22, 33, 23, 13, 12)
  static constexpr std::array<int, 3> given_index{0, 5, 4};
  static constexpr std::array<int, 3> free_index{1, 2, 3};
};

/// A 3D law that exposes the effective (undamaged) stress and tangent of its response.
template <class Response>
concept HasEffectiveResponse = requires(const Response& response) {
  response.effective_stress;
  response.effective_tangent;
};

template <class Law3D, FiberStressState kind = FiberStressState::uniaxial> class FiberCondensation {
  using Components = FiberComponents<kind>;
  static constexpr int kGiven = Components::given;
  static constexpr int kFree = 6 - kGiven;

public:
  using GivenVector = Eigen::Matrix<double, kGiven, 1>;
  using GivenMatrix = Eigen::Matrix<double, kGiven, kGiven>;
  using FreeVector = Eigen::Matrix<double, kFree, 1>;

  struct State {
    typename Law3D::State material;
    FreeVector free_strain = FreeVector::Zero(); ///< committed lateral strains (Voigt)
  };
  struct Response {
    GivenVector stress;
    GivenMatrix tangent;
    State state;
    int iterations = 0;
    bool converged = false;
  };

  explicit FiberCondensation(Law3D law, int max_iterations = 40)
      : law_(std::move(law)), max_iterations_(max_iterations) {}

  State initial_state() const { return State{law_.initial_state(), FreeVector::Zero()}; }
  const Law3D& law() const { return law_; }

  Response evaluate(const State& committed, const GivenVector& given_strain) const {
    Vector6 strain = Vector6::Zero();
    for (int i = 0; i < kGiven; ++i)
      strain[Components::given_index[i]] = given_strain[i];
    FreeVector free_strain = committed.free_strain;

    Response result;
    for (int iteration = 0; iteration <= max_iterations_; ++iteration) {
      for (int i = 0; i < kFree; ++i)
        strain[Components::free_index[i]] = free_strain[i];
      auto response = law_.evaluate(committed.material, strain);
      const auto& [residual_stress, residual_tangent] = newton_system(response);
      FreeVector residual;
      Eigen::Matrix<double, kFree, kFree> free_tangent;
      for (int i = 0; i < kFree; ++i) {
        residual[i] = residual_stress[Components::free_index[i]];
        for (int j = 0; j < kFree; ++j) {
          free_tangent(i, j) =
              residual_tangent(Components::free_index[i], Components::free_index[j]);
        }
      }
      const auto factor = free_tangent.partialPivLu();
      const bool last = iteration == max_iterations_;
      // Converged when the free stresses are round-off small against the stress level.
      const double tolerance =
          1e-13 * (law_.stress_scale() + residual_stress.template lpNorm<Eigen::Infinity>());
      const bool converged = residual.template lpNorm<Eigen::Infinity>() <= tolerance;
      if (converged || last || !residual.allFinite()) {
        // Static condensation of the free strains.
        Eigen::Matrix<double, kGiven, kFree> given_free;
        Eigen::Matrix<double, kFree, kGiven> free_given;
        for (int i = 0; i < kGiven; ++i) {
          result.stress[i] = response.stress[Components::given_index[i]];
          for (int j = 0; j < kGiven; ++j) {
            result.tangent(i, j) =
                response.tangent(Components::given_index[i], Components::given_index[j]);
          }
          for (int j = 0; j < kFree; ++j) {
            given_free(i, j) =
                response.tangent(Components::given_index[i], Components::free_index[j]);
            free_given(j, i) =
                residual_tangent(Components::free_index[j], Components::given_index[i]);
          }
        }
        // With an effective response, sigma_bar_f = 0 makes the nominal free rows
        // (1 - d) times the effective ones, so C_gf [(1-d) C_bar_ff]^-1 (1-d) C_bar_fg needs
        // only the effective free rows: exact, and regular as d -> 1.
        result.tangent -= given_free * factor.solve(free_given);
        result.state.material = std::move(response.state);
        result.state.free_strain = free_strain;
        result.iterations = iteration;
        result.converged = converged;
        return result;
      }
      free_strain -= factor.solve(residual);
    }
    return result; // not reached
  }

private:
  template <class Response>
  static std::pair<const Vector6&, const Matrix6&> newton_system(const Response& response) {
    if constexpr (HasEffectiveResponse<Response>) {
      return {response.effective_stress, response.effective_tangent};
    } else {
      return {response.stress, response.tangent};
    }
  }

  Law3D law_;
  int max_iterations_;
};

} // namespace brb::material
