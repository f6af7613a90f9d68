// The least-squares power law of `brb bench scaling` on synthetic data whose exponent is known,
// the median of the repeats, and the generated frames of the brace series.
#include "brb/study/scaling_fit.hpp"
#include "brb/study/scaling_study.hpp"
#include "brb/study/skips_study.hpp"

#include "brb/io/frame_input.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <variant>
#include <vector>

namespace {

using namespace brb;

// cost = 0.02 n^1.7 exactly: the fit returns b = 1.7, a = ln 0.02, R^2 = 1 (to round-off)
TEST(ScalingFit, RecoversAnExactPowerLaw) {
  const std::vector<double> sizes{1.0, 4.0, 16.0, 64.0};
  std::vector<double> costs;
  for (const double n : sizes)
    costs.push_back(0.02 * std::pow(n, 1.7));
  const study::PowerLawFit fit = study::fit_power_law(sizes, costs);
  EXPECT_NEAR(fit.exponent, 1.7, 1e-12);
  EXPECT_NEAR(fit.intercept, std::log(0.02), 1e-12);
  EXPECT_NEAR(fit.r_squared, 1.0, 1e-12);
}

// Two-point scatter about a line: with x = ln n at (0, ln 2) and y = b x + e, e = +d, -d, -d, +d
// at x = 0, ln2, 2 ln2, 3 ln2 the centred x are (-1.5, -0.5, 0.5, 1.5) ln 2, so sum x e = 0:
// the least-squares slope is exactly b despite the scatter (hand computation), R^2 < 1.
TEST(ScalingFit, SymmetricScatterLeavesTheSlope) {
  const double b = 0.9, d = 0.1;
  const std::vector<double> sizes{1.0, 2.0, 4.0, 8.0};
  const std::vector<double> noise{d, -d, -d, d};
  std::vector<double> costs;
  for (std::size_t k = 0; k < sizes.size(); ++k)
    costs.push_back(std::exp(b * std::log(sizes[k]) + noise[k]));
  const study::PowerLawFit fit = study::fit_power_law(sizes, costs);
  EXPECT_NEAR(fit.exponent, b, 1e-12);
  EXPECT_NEAR(fit.intercept, 0.0, 1e-12); // mean of e is 0
  EXPECT_LT(fit.r_squared, 1.0);
  EXPECT_GT(fit.r_squared, 0.9);
}

TEST(ScalingFit, RejectsWhatCannotBeFitted) {
  const std::vector<double> one{1.0};
  EXPECT_THROW(study::fit_power_law(one, one), std::invalid_argument);
  const std::vector<double> sizes{1.0, 2.0}, zero{1.0, 0.0}, equal{3.0, 3.0};
  EXPECT_THROW(study::fit_power_law(sizes, zero), std::invalid_argument);
  EXPECT_THROW(study::fit_power_law(equal, sizes), std::invalid_argument);
  const std::vector<double> three{1.0, 2.0, 3.0};
  EXPECT_THROW(study::fit_power_law(sizes, three), std::invalid_argument);
}

TEST(ScalingFit, MedianOfOddAndEvenCounts) {
  const std::vector<double> odd{3.0, 1.0, 2.0}, even{4.0, 1.0, 3.0, 2.0};
  EXPECT_EQ(study::median(odd), 2.0);
  EXPECT_EQ(study::median(even), 2.5);
  EXPECT_THROW(study::median(std::vector<double>{}), std::invalid_argument);
}

// The brace series' frames: N braces, N bays, N + 1 columns, one storey, every node of the floor
// with the first floor node's mass of brbf3.
TEST(ScalingStudy, GeneratedFrameHasOneBracePerBay) {
  const model::FrameSpec base = io::read_frame(BRB_SOURCE_DIR "/frames/brbf3/model.json");
  for (const int braces : {1, 4, 16}) {
    const model::FrameSpec spec = study::generated_frame(base, braces);
    int brace_count = 0, beam_count = 0;
    for (const model::FrameElementSpec& element : spec.elements) {
      if (std::holds_alternative<model::BraceElementSpec>(element.kind)) {
        ++brace_count;
        // the brace's work points are its length apart (the builder checks it too)
        const auto& brace = std::get<model::BraceElementSpec>(element.kind);
        EXPECT_NEAR(spec.element_length(element), brace.brace.total_length(),
                    1e-9 * brace.brace.total_length());
      } else {
        ++beam_count;
      }
    }
    EXPECT_EQ(brace_count, braces);
    EXPECT_EQ(beam_count, 2 * braces + 1); // N + 1 columns and N beams
    EXPECT_EQ(spec.nodes.size(), 2u * (braces + 1));
    EXPECT_EQ(spec.masses.size(), static_cast<std::size_t>(braces + 1));
    EXPECT_EQ(spec.stories.size(), 1u);
  }
  EXPECT_THROW(study::generated_frame(base, 0), std::invalid_argument);
}

TEST(SkipsStudy, EverySkipIsSwitchedOffAloneOnce) {
  const auto skips = study::named_skips();
  ASSERT_EQ(skips.size(), 5u);
  for (const study::NamedSkip& skip : skips) {
    const model::WorkSkips& off = skip.off;
    const int switched_off = !off.open_links + !off.elastic_fast_path + !off.reuse_tangents +
                             !off.requested_recorders + !off.auto_fidelity;
    EXPECT_EQ(switched_off, 1) << skip.name;
  }
}

} // namespace
