// The K3.4c qualification sequence (ANSI/AISC 341-16, AISC341_NOTES.md) against hand-written
// sequences, and the elastic-perfectly plastic count of the step-6 cycles.
#include "brb/design/loading_sequence.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace brb::design {
namespace {

const EditionParameters kEdition = edition_parameters(Edition::aisc341_16);

/// Amplitudes of the cycles, one per cycle, in order.
std::vector<double> cycle_amplitudes(const std::vector<io::CycleGroup>& groups) {
  std::vector<double> amplitudes;
  for (const io::CycleGroup& group : groups)
    amplitudes.insert(amplitudes.end(), static_cast<std::size_t>(group.cycles), group.amplitude);
  return amplitudes;
}

TEST(QualificationSequence, MatchesTheStandardsListWithTheExtraCyclesCountedByHand) {
  // Delta_by = 2 mm, Delta_bm = 10 mm. By hand (K3.4c): 2 at 2, 2 at 5, 2 at 10, 2 at 15,
  // 2 at 20 mm. Elastic-perfectly plastic count, 4 (A - Delta_by) / Delta_by per cycle:
  // 0 + 2 x 6 + 2 x 16 + 2 x 26 + 2 x 36 = 168 Delta_by; each cycle at 15 mm adds 26, so
  // 200 needs ceil(32 / 26) = 2 more cycles at 15 mm.
  const QualificationSequence sequence = qualification_sequence(2.0, 10.0, kEdition);
  EXPECT_DOUBLE_EQ(estimated_inelastic_deformation_before_extra(sequence), 168.0);
  EXPECT_DOUBLE_EQ(sequence.extra_amplitude, 15.0);
  EXPECT_DOUBLE_EQ(sequence.cumulative_target, 200.0);
  const int extra = estimated_extra_cycles(sequence);
  EXPECT_EQ(extra, 2);
  const std::vector<double> hand_written{2, 2, 5, 5, 10, 10, 15, 15, 20, 20, 15, 15};
  EXPECT_EQ(cycle_amplitudes(sequence_groups(sequence, extra)), hand_written);
}

TEST(QualificationSequence, AnExactMultipleNeedsNoCycleMore) {
  // Delta_by = 1, Delta_bm = 3: per cycle 0, 2, 8, 14, 20 -> 88 over steps 1-5; each cycle at
  // 4.5 adds 14 and (200 - 88) / 14 = 8 exactly: 8 cycles, not 9.
  const QualificationSequence sequence = qualification_sequence(1.0, 3.0, kEdition);
  EXPECT_DOUBLE_EQ(estimated_inelastic_deformation_before_extra(sequence), 88.0);
  EXPECT_EQ(estimated_extra_cycles(sequence), 8);
  const std::vector<double> hand_written{1, 1,   1.5, 1.5, 3,   3,   4.5, 4.5, 6,
                                         6, 4.5, 4.5, 4.5, 4.5, 4.5, 4.5, 4.5, 4.5};
  EXPECT_EQ(cycle_amplitudes(sequence_groups(sequence, 8)), hand_written);
}

TEST(QualificationSequence, LargeDesignDeformationsReachTheTargetWithoutStepSix) {
  // Delta_by = 1, Delta_bm = 12: 2 x (0 + 20 + 44 + 68 + 92) = 448 >= 200.
  const QualificationSequence sequence = qualification_sequence(1.0, 12.0, kEdition);
  EXPECT_DOUBLE_EQ(estimated_inelastic_deformation_before_extra(sequence), 448.0);
  EXPECT_EQ(estimated_extra_cycles(sequence), 0);
  EXPECT_EQ(sequence_groups(sequence, 0).size(), 5U);
}

TEST(QualificationSequence, CyclesWithinTheElasticRangeAddNothing) {
  EXPECT_DOUBLE_EQ(estimated_cycle_inelastic_deformation(0.8, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(estimated_cycle_inelastic_deformation(1.0, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(estimated_cycle_inelastic_deformation(3.0, 1.0), 8.0);
}

TEST(QualificationSequence, RejectsDeformationsStepSixCannotUse) {
  EXPECT_THROW(qualification_sequence(0.0, 1.0, kEdition), std::invalid_argument);
  EXPECT_THROW(qualification_sequence(1.0, -1.0, kEdition), std::invalid_argument);
  // 1.5 Delta_bm = 0.9 Delta_by: step 6 never yields, the target cannot be reached.
  const QualificationSequence elastic = qualification_sequence(1.0, 0.6, kEdition);
  EXPECT_THROW(estimated_extra_cycles(elastic), std::invalid_argument);
}

TEST(QualificationSequence, TheProtocolIsTensionFirstWithExactTurningPoints) {
  const QualificationSequence sequence = qualification_sequence(2.0, 10.0, kEdition);
  const io::LoadingProtocol protocol =
      io::cyclic_protocol("K3.4c", sequence_groups(sequence, 2), 0.5);
  ASSERT_EQ(protocol.cycle_count(), 12U);
  // Turning points: the extremes of each cycle are +A and -A exactly.
  std::vector<double> highest(12, 0.0);
  std::vector<double> lowest(12, 0.0);
  for (std::size_t k = 1; k < protocol.deformation.size(); ++k) {
    const std::size_t c = static_cast<std::size_t>(protocol.cycle[k] - 1);
    highest[c] = std::max(highest[c], protocol.deformation[k]);
    lowest[c] = std::min(lowest[c], protocol.deformation[k]);
  }
  const std::vector<double> amplitudes = cycle_amplitudes(sequence_groups(sequence, 2));
  for (std::size_t c = 0; c < 12; ++c) {
    EXPECT_DOUBLE_EQ(highest[c], amplitudes[c]) << c;
    EXPECT_DOUBLE_EQ(lowest[c], -amplitudes[c]) << c;
  }
}

} // namespace
} // namespace brb::design
