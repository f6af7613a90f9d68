// Reversals (turning points) of a measured deformation history: the places where the
// deformation changes direction by more than a noise threshold. A measured record
// chatters: electrical noise and actuator hunting make it go back and forth by small
// amounts, and every such wiggle would otherwise count as a reversal (and a "cycle").
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace brb::validation {

/// Indices of the turning points of `deformation` (mm), in order, first and last points
/// excluded. Hysteresis rule (a "zig-zag" filter): while the history goes one way, its
/// running extreme is a candidate; it becomes a reversal once the history has come back from
/// it by more than `threshold` (mm, >= 0). So each reversal is the exact extreme point of the
/// record between two reversals (the peak amplitude is kept to the record's resolution), and
/// a wiggle smaller than `threshold` never makes one. Consecutive reversals alternate
/// between maxima and minima. Throws std::invalid_argument for a negative or non-finite
/// threshold.
std::vector<std::size_t> find_reversals(std::span<const double> deformation, double threshold);

} // namespace brb::validation
