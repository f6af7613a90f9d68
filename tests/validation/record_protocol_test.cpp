// Protocol extraction from a record's deformation history, on synthetic noisy triangle waves
// whose turning points are known by construction.
#include "brb/validation/record_protocol.hpp"
#include "brb/validation/reversals.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace brb::validation {
namespace {

/// A triangle wave 0 -> +A1 -> -A1 -> +A2 -> -A2 ... -> 0 sampled every `spacing` mm, with
/// uniform noise of +-noise added to every point but the first; `peaks` receives the sample
/// indices of the exact turning points.
std::vector<double> noisy_triangle_wave(const std::vector<double>& amplitudes, double spacing,
                                        double noise, std::vector<std::size_t>& peaks) {
  std::vector<double> targets;
  for (const double amplitude : amplitudes) {
    targets.push_back(amplitude);
    targets.push_back(-amplitude);
  }
  targets.push_back(0.0);
  std::mt19937 generator(7);
  std::uniform_real_distribution<double> wiggle(-noise, noise);
  std::vector<double> history{0.0};
  double position = 0.0;
  for (const double target : targets) {
    const auto steps = static_cast<int>(std::round(std::abs(target - position) / spacing));
    for (int i = 1; i <= steps; ++i)
      history.push_back(position + (target - position) * i / steps + wiggle(generator));
    position = target;
    peaks.push_back(history.size() - 1);
  }
  peaks.pop_back(); // the final return to 0 is the end, not a turning point
  return history;
}

TEST(Reversals, FindsEveryTurningPointOfANoisyTriangleWaveAndNoNoise) {
  const std::vector<double> amplitudes{1.0, 2.0, 3.0, 3.0};
  const double noise = 0.02; // below half the threshold: no wiggle can pass for a reversal
  std::vector<std::size_t> peaks;
  const std::vector<double> history = noisy_triangle_wave(amplitudes, 0.01, noise, peaks);
  const std::vector<std::size_t> reversals = find_reversals(history, 0.1);
  ASSERT_EQ(reversals.size(), 2 * amplitudes.size());
  for (std::size_t k = 0; k < reversals.size(); ++k) {
    const double amplitude = (k % 2 == 0 ? 1.0 : -1.0) * amplitudes[k / 2];
    // The reversal is the running extreme near the true peak: within the noise of it.
    EXPECT_NEAR(history[reversals[k]], amplitude, noise) << "reversal " << k;
    EXPECT_LE(std::abs(static_cast<double>(reversals[k]) - static_cast<double>(peaks[k])), 4.0)
        << "reversal " << k << " far from the true turning point";
  }
  // Without a threshold, the noise makes thousands of "reversals".
  EXPECT_GT(find_reversals(history, 0.0).size(), 100u);
}

TEST(Reversals, NoneForAMonotonicHistoryAndTheStartIsNotOne) {
  EXPECT_TRUE(find_reversals(std::vector<double>{0, 1, 2, 3, 2.95, 4}, 0.1).empty());
  // Falls first by less than the threshold, then rises and comes back: one maximum.
  const std::vector<double> history{0.0, -0.05, 1.0, 2.0, 0.5};
  EXPECT_EQ(find_reversals(history, 0.1), (std::vector<std::size_t>{3}));
  EXPECT_THROW(find_reversals(history, -1.0), std::invalid_argument);
}

TEST(RecordProtocol, KeepsReversalsCapsStepsAndMapsEveryPointToItsRecordPoint) {
  const std::vector<double> amplitudes{1.0, 2.0, 3.0, 3.0};
  const double noise = 0.02;
  std::vector<std::size_t> peaks;
  const std::vector<double> history = noisy_triangle_wave(amplitudes, 0.01, noise, peaks);
  const RecordProtocolOptions options{0.1, 0.25};
  const RecordProtocol protocol = extract_record_protocol(history, options);

  ASSERT_EQ(protocol.deformation.size(), protocol.record_index.size());
  EXPECT_EQ(protocol.deformation.front(), 0.0);
  EXPECT_EQ(protocol.record_index.front(), RecordProtocol::kNoRecordPoint);
  // Much thinner than the record: about total travel / max_step points, not 3,000.
  const double travel = 2 * (1 + 2 + 3 + 3) * 2.0; // each amplitude twice up and twice down
  EXPECT_LT(protocol.size(), static_cast<std::size_t>(travel / options.max_step) * 2);
  EXPECT_GE(protocol.size(), static_cast<std::size_t>(travel / options.max_step));

  std::size_t previous_index = 0;
  for (std::size_t k = 1; k < protocol.size(); ++k) {
    EXPECT_LE(std::abs(protocol.deformation[k] - protocol.deformation[k - 1]),
              options.max_step * (1 + 1e-12))
        << "step " << k;
    const std::size_t index = protocol.record_index[k];
    if (index == RecordProtocol::kNoRecordPoint)
      continue;
    EXPECT_EQ(protocol.deformation[k], history[index]) << "point " << k;
    EXPECT_GE(index, previous_index) << "record points out of order at " << k;
    previous_index = index;
  }
  EXPECT_EQ(protocol.record_index.back(), history.size() - 1);

  // Every reversal is a protocol point, with the record's amplitude within the noise.
  ASSERT_EQ(protocol.reversal_points.size(), 2 * amplitudes.size());
  for (std::size_t k = 0; k < protocol.reversal_points.size(); ++k) {
    const double amplitude = (k % 2 == 0 ? 1.0 : -1.0) * amplitudes[k / 2];
    EXPECT_NEAR(protocol.deformation[protocol.reversal_points[k]], amplitude, noise);
  }
}

TEST(RecordProtocol, FillsJumpsOfTheRecordWithUncomparedPoints) {
  // Starts at 0.05 (not 0), jumps from 0.1 to 1.1 between two samples.
  const std::vector<double> history{0.05, 0.1, 1.1, 1.2};
  const RecordProtocol protocol = extract_record_protocol(history, {0.1, 0.25});
  // 0.05 adds nothing (0.1 is within reach of 0); 0.1 -> 1.1 is cut into 4 equal steps.
  const std::vector<double> expected{0.0, 0.1, 0.35, 0.6, 0.85, 1.1, 1.2};
  ASSERT_EQ(protocol.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k)
    EXPECT_NEAR(protocol.deformation[k], expected[k], 1e-12) << k;
  const auto none = RecordProtocol::kNoRecordPoint;
  EXPECT_EQ(protocol.record_index, (std::vector<std::size_t>{none, 1, none, none, none, 2, 3}));
  EXPECT_THROW(extract_record_protocol(history, {0.1, 0.0}), std::invalid_argument);
}

} // namespace
} // namespace brb::validation
