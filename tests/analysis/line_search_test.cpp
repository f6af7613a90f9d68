// projected_line_search (brb/analysis/line_search.hpp): the root of the projected residual
// s(eta) = du . r(u + eta du) on (0, 1). References: the roots of the test functions in
// closed form.
#include "brb/analysis/line_search.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace brb::analysis {
namespace {

/// s(eta) for one DOF u pulled by a load F through a soft spring k towards a stiff contact at
/// a gap g, du the Newton step of the open spring: r(u) = F - k u - k_c <u - g>, from u = 0,
/// du = F / k. The potential's least value along du is at u* = (F + k_c g) / (k + k_c).
struct ContactLine {
  double load = 1.0, spring = 1.0, contact = 1e3, gap = 1e-3;
  double step() const { return load / spring; }
  double slope(double eta) const {
    const double u = eta * step();
    const double residual = load - spring * u - contact * std::max(u - gap, 0.0);
    return step() * residual;
  }
  double root() const { return (load + contact * gap) / (spring + contact) / step(); }
};

TEST(ProjectedLineSearch, FindsTheLeastPotentialPastAContactKink) {
  // Backtracking on |r| fails here down to 1/64 of the step (u = 0.0156 is 15 gaps deep in
  // the contact, |r| = 13.6 against 1 at the start); s changes sign at u* = 1.998e-3.
  const ContactLine line;
  EXPECT_GT(std::abs(line.slope(1.0 / 64.0)) / line.step(), std::abs(line.load));
  std::vector<double> tried;
  const bool found =
      projected_line_search(line.slope(0.0), line.slope(1.0), [&](double eta, double& slope) {
        tried.push_back(eta);
        slope = line.slope(eta);
        return true;
      });
  ASSERT_TRUE(found);
  ASSERT_FALSE(tried.empty());
  const double eta = tried.back();
  EXPECT_LE(std::abs(line.slope(eta)), 0.5 * line.slope(0.0));
  // Within the accepted band around the root: |s| <= s(0) / 2 means |u - u*| <= F / (2
  // (k + k_c)) on the contact side, 5e-4 here (on the open side |s| is about s(0)).
  EXPECT_NEAR(eta * line.step(), line.root() * line.step(), 0.5 * line.load / line.contact);
  EXPECT_LE(tried.size(), 8U);
}

TEST(ProjectedLineSearch, IllinoisShrinksTheBracketFromBothSides) {
  // s = 1 - 20 eta^4, convex: plain regula falsi keeps the high end and creeps up to the root
  // (0.05^(1/4) = 0.4729) from below, still outside the band after 8 evaluations (measured);
  // halving the kept end's value (Illinois) brings it within in 5.
  const auto slope_of = [](double eta) { return 1.0 - 20.0 * std::pow(eta, 4); };
  int evaluations = 0;
  double last = 0.0;
  const bool found =
      projected_line_search(slope_of(0.0), slope_of(1.0), [&](double eta, double& slope) {
        ++evaluations;
        last = eta;
        slope = slope_of(eta);
        return true;
      });
  ASSERT_TRUE(found);
  EXPECT_LE(std::abs(slope_of(last)), 0.5);
  EXPECT_NEAR(last, std::pow(0.05, 0.25), 0.05);
  EXPECT_LE(evaluations, 5);
}

TEST(ProjectedLineSearch, GivesUpPastItsBudgetOnAContactFarStifferThanTheStep) {
  // The limit of regula falsi at a kink: with k_c / k = 1e5 each evaluation lands on the open
  // side just above the last one, and the Illinois halvings need about log2(1e5) = 17 of them
  // to move the far end's value; the caller then takes the backtracking's shortest step.
  ContactLine line;
  line.contact = 1e5;
  int evaluations = 0;
  EXPECT_FALSE(
      projected_line_search(line.slope(0.0), line.slope(1.0), [&](double eta, double& slope) {
        ++evaluations;
        slope = line.slope(eta);
        return true;
      }));
  EXPECT_EQ(evaluations, 8);
}

TEST(ProjectedLineSearch, RefusesWithoutASignChangeOrADescentDirection) {
  int evaluations = 0;
  const auto count = [&](double, double& slope) {
    ++evaluations;
    slope = 0.0;
    return true;
  };
  EXPECT_FALSE(projected_line_search(1.0, 0.5, count));   // least potential beyond the step
  EXPECT_FALSE(projected_line_search(-1.0, -2.0, count)); // du not a descent direction
  EXPECT_FALSE(projected_line_search(0.0, -1.0, count));
  EXPECT_FALSE(projected_line_search(std::nan(""), -1.0, count));
  EXPECT_EQ(evaluations, 0);
}

TEST(ProjectedLineSearch, StopsWhenAStateCannotBeEvaluated) {
  int evaluations = 0;
  EXPECT_FALSE(projected_line_search(1.0, -1.0, [&](double, double&) {
    ++evaluations;
    return false;
  }));
  EXPECT_EQ(evaluations, 1);
  EXPECT_FALSE(projected_line_search(1.0, -1.0, [](double, double& slope) {
    slope = std::nan("");
    return true;
  }));
}

} // namespace
} // namespace brb::analysis
