// A small linear elastic frame for IDA tests: a two-storey planar cantilever column (linear
// geometry, no gravity, Rayleigh damping) whose peak response is exactly proportional to the
// ground-motion scale, and a suite of two shared records.
#pragma once

#include <string_view>

namespace brb::test {

inline constexpr std::string_view kLinearFrame = R"({
  "title": "linear two-storey cantilever",
  "dimension": 2,
  "nodes": [{"id": 1, "xyz": [0, 0, 0]}, {"id": 2, "xyz": [0, 0, 3000]},
            {"id": 3, "xyz": [0, 0, 6000]}],
  "supports": [{"node": 1, "fix": "fixed"}],
  "masses": [{"node": 2, "mass": 20}, {"node": 3, "mass": 15}],
  "sections": {"S": {"E": 200000, "G": 77000, "A": 20000, "Iy": 4e8, "Iz": 4e8, "J": 1e6}},
  "elements": [
    {"id": 1, "type": "elastic_beam", "nodes": [1, 2], "section": "S", "geometry": "linear"},
    {"id": 2, "type": "elastic_beam", "nodes": [2, 3], "section": "S", "geometry": "linear"}
  ],
  "damping": {"type": "rayleigh", "modes": [1, 2], "ratios": [0.02, 0.02]},
  "stories": [{"name": "1", "bottom": 1, "top": 2}, {"name": "2", "bottom": 2, "top": 3}],
  "floors": [{"name": "1", "node": 2}, {"name": "2", "node": 3}]
})";

/// Two shared records (../shared/data/ground_motions) for short test suites.
inline constexpr std::string_view kTwoRecordNames[] = {"elCentro.AT2", "ARL360.at2"};

} // namespace brb::test
