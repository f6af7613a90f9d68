// WorkSkips: the switches of the work a scene does not need (DESIGN.md section 10), all on by
// default. The benchmark (`brb bench skips`) switches each off to measure what it saves and
// what error it adds. Lower layers take the one switch that concerns them as a plain bool
// (material, element) so that they do not depend on the model layer; the builders of the
// model layer (build_brace_model, add_brace_to_model) and of frames hand them down.
//
//   open_links          CasingContact: a link whose faces are all open (penetration with the
//                       core's expansion <= 0) returns its constant layer tangent (cached,
//                       sized for its 2 to 4 nodes) without the bearing and friction laws.
//                       Exact.
//   elastic_fast_path   SteelUniaxial: a fiber below yield and below its damage threshold
//                       returns E and its committed state without the return map's energy
//                       bookkeeping. Exact (the skipped terms add zero).
//   reuse_tangents      BRBElement (condensed): an element asked again at the configuration of
//                       its last evaluation, whose committed history has not changed since
//                       (no dissipation), returns that evaluation's forces and tangent instead
//                       of solving its internal brace again. Not bit-exact: a re-solve starts
//                       from another internal state and may land on a slightly different
//                       internal equilibrium (the core in contact has many near-equal ones);
//                       `brb bench skips` measures the difference.
//   requested_recorders frame recorders build only the histories asked for. Exact.
//   auto_fidelity       `auto` braces run as `truss` where the rule of brace_fidelity.hpp says
//                       so; off, every `auto` brace runs as `full`. Not exact: the bench
//                       measures its error.
#pragma once

namespace brb::model {

struct WorkSkips {
  bool open_links = true;
  bool elastic_fast_path = true;
  bool reuse_tangents = true;
  bool requested_recorders = true;
  bool auto_fidelity = true;

  /// Every skip off: the reference of the benchmark.
  static WorkSkips none() { return {false, false, false, false, false}; }

  bool operator==(const WorkSkips&) const = default;
};

} // namespace brb::model
