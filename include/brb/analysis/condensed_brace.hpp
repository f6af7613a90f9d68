// A stand-alone brace as one condensed BRBElement (DESIGN.md section 4: the brace solved inside
// a two-node element, its internal DOF statically condensed) between two outer nodes along x,
// held as build_brace_model holds its ends, and its cyclic test: the same protocol, the same
// hysteresis metrics as run_cyclic_test on the expanded brace model. Both solve the same
// equations (tests/slow/brb_element_restrained_test.cpp: forces within 1e-6); the condensed
// one pays for the nested solve, which is what the run-time-against-error study measures
// (`brb bench pareto`, a component setting's "mode": "condensed").
#pragma once

#include "brb/analysis/brb_element.hpp"
#include "brb/analysis/cyclic_test.hpp"
#include "brb/analysis/static_analysis.hpp"
#include "brb/model/brace_spec.hpp"
#include "brb/model/model.hpp"

#include <memory>
#include <span>

namespace brb::analysis {

/// The global model: the brace's two outer nodes (start at the origin, end at the brace's
/// length along x), held as build_brace_model holds them (model::hold_stand_alone_ends), and
/// one condensed BRBElement between them.
struct CondensedBraceModel {
  model::Model model;
  int start_node = 0;
  int end_node = 0;
  BRBElement* element = nullptr;
};

/// `settings`: the element's nested Newton (BRBElement adds its polishing correction).
std::unique_ptr<CondensedBraceModel> build_condensed_brace_model(const model::BraceSpec& spec,
                                                                 NewtonSettings settings = {});

/// The cyclic test of the condensed brace: the end node driven along x through `deformation`
/// (its first point is the start, 0), the force the driven node needs, per step and per
/// cycle as run_cyclic_test. `settings`: the outer Newton's. The result's steps, cycles,
/// completion, stop reason and solver statistics are filled (the outer solver's; the element's
/// internal solves are inside its evaluations); indicators and histories are not.
CyclicTestResult run_condensed_cyclic_test(CondensedBraceModel& brace,
                                           std::span<const double> deformation,
                                           std::span<const int> cycle,
                                           std::span<const double> cycle_amplitude,
                                           NewtonSettings settings = {});

} // namespace brb::analysis
