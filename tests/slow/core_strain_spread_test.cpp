// Where a restrained core's plastic strain goes under cyclic casing friction: the PC160
// laboratory brace (validation/PC160, gaaraujo/BRB-Calibration; 12 core elements of 372.5 mm
// in a 1 mm clearance, the sub-element waves on), one cycle at 40 mm, then two at 75 mm
// (1.7 % mean core strain). Slow: about a minute.
//
// Why it matters (validation/CALIBRATION.md, "Where the waves' beta comes from"): the waves'
// friction is largest where the core yields, so with a hardening that saturates the end
// elements took all the compressive strain and ratcheted it cycle by cycle (end elements 56 mm
// shorter at the first 75 mm peak, 229 mm at the eighth, the inner ones longer), the casing
// ratcheted sideways and the brace buckled globally. The tests show waves and strain along the
// whole core (Wu, Lin & Tsai 2014, Earthquake Engng Struct. Dyn. 43). The brace files' steel
// keeps a linear kinematic hardening (H_kin = E / 100) that stops it.
#include "brb/analysis/cyclic_test.hpp"
#include "brb/io/brace_input.hpp"
#include "brb/io/protocol.hpp"
#include "brb/model/brace_model.hpp"
#include "support/specimen_files.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace brb::analysis {
namespace {

/// The core elements' chord strains at one step, from the shape's nodes (each node but the
/// last gives the element that starts there).
std::vector<double> element_strains(const std::vector<BraceShapeNode>& shapes, int step) {
  std::map<int, double> by_node;
  for (const BraceShapeNode& node : shapes)
    if (node.step == step)
      by_node[node.node] = node.core_axial_strain;
  std::vector<double> strains;
  for (const auto& [node, strain] : by_node)
    strains.push_back(strain);
  if (!strains.empty())
    strains.pop_back(); // the last node repeats the element ending there
  return strains;
}

/// Largest compressive chord strain over the mean chord strain of the elements.
double localisation(const std::vector<double>& strains) {
  double sum = 0.0;
  double most_compressed = 0.0;
  for (const double strain : strains) {
    sum += strain;
    most_compressed = std::min(most_compressed, strain);
  }
  const double mean = sum / static_cast<double>(strains.size());
  return most_compressed / mean;
}

struct SpreadRun {
  double first_localisation = 0.0;  ///< at the first 75 mm compression peak
  double second_localisation = 0.0; ///< at the second
  double balance_error = 0.0;
};

/// PC160's brace with its own steel, or with its linear kinematic hardening taken out
/// (`saturating`: what is left, the back stresses and Voce, saturates).
SpreadRun run_pc160(bool saturating) {
  model::BraceSpec spec = io::read_brace(test::specimen_brace("PC160"));
  EXPECT_TRUE(spec.casing.has_value() && spec.casing->high_mode_waves.has_value());
  EXPECT_GT(spec.steel.kinematic_hardening, 0.0);
  if (saturating)
    spec.steel.kinematic_hardening = 0.0;
  model::BraceModel brace = model::build_brace_model(spec);
  const double dy = brace.yield_deformation;
  const io::LoadingProtocol protocol =
      io::cyclic_protocol("pc160", {{40.0, 1}, {75.0, 2}}, dy / 10.0);
  // the compression peaks of the 75 mm cycles (CyclicStep numbering: point k is step k)
  std::vector<int> peaks;
  for (std::size_t k = 0; k < protocol.deformation.size(); ++k)
    if (std::abs(protocol.deformation[k] + 75.0) < 1e-9)
      peaks.push_back(static_cast<int>(k));
  EXPECT_EQ(peaks.size(), 2u);
  NewtonSettings settings;
  // balance control for the brace file's steel: without it this short history misses the
  // 1e-6 (1.1e-6 measured); the saturating counter-example runs without it (faster)
  if (!saturating)
    settings.balance_tolerance = 5e-7;
  const CyclicTestResult result = run_cyclic_test(brace, protocol.deformation, protocol.cycle,
                                                  protocol.cycle_amplitude, settings, false, peaks);
  EXPECT_TRUE(result.completed) << result.stop_reason;
  SpreadRun run;
  run.balance_error = result.energy_balance.relative_error();
  if (peaks.size() != 2u || !result.completed)
    return run;
  const std::vector<double> first = element_strains(result.shapes, peaks[0]);
  const std::vector<double> second = element_strains(result.shapes, peaks[1]);
  EXPECT_EQ(first.size(), static_cast<std::size_t>(spec.core_elements));
  EXPECT_EQ(second.size(), first.size());
  run.first_localisation = localisation(first);
  run.second_localisation = localisation(second);
  std::cout << "[ spread ] PC160, " << (saturating ? "saturating hardening" : "its own steel")
            << ": most compressed element over the mean at the 75 mm compression peaks "
            << run.first_localisation << " then " << run.second_localisation
            << "; chord strains at the second (%):";
  for (const double strain : second)
    std::cout << " " << 100.0 * strain;
  std::cout << "; balance " << run.balance_error << "\n";
  return run;
}

TEST(CoreStrainSpread, CyclicFrictionLocalisesTheCoresStrainOnlyBoundedlyWithGrowingHardening) {
  // References: uniform strain gives a ratio of 1. The friction grows from the stopper to
  // the core's ends, so the end elements carry more compression and shorten more; a hardening
  // that keeps growing (linear kinematic) bounds that excess, a saturating one does not
  // (session 21, CALIBRATION.md: 56.2 mm against 6.2 mm uniform, a ratio of 9, at the first
  // peak, growing every cycle). The bound 4 sits between the two behaviours; the repeated
  // cycle must not push more strain into the ends (within 10 %), while without the growing
  // term it does.
  const SpreadRun hardening = run_pc160(false);
  const SpreadRun saturating = run_pc160(true);
  EXPECT_LT(hardening.first_localisation, 4.0);
  EXPECT_LT(hardening.second_localisation, 4.0);
  EXPECT_LT(hardening.second_localisation, 1.1 * hardening.first_localisation);
  EXPECT_GT(saturating.first_localisation, 4.0);
  EXPECT_GT(saturating.second_localisation, 1.1 * saturating.first_localisation);
  EXPECT_LT(hardening.balance_error, 1e-6);
}

} // namespace
} // namespace brb::analysis
