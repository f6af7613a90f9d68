// ElementEvaluations (the element loop of an assembly, on one thread or several): every
// element is evaluated exactly once per loop into its own force and tangent whatever the
// thread count; a failure reported is the first failing element's in element order, as on
// one thread; a non-finite force is a failure naming its element; elements left out are not
// evaluated.
#include "brb/model/element_evaluations.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace brb::model {
namespace {

/// A spring between a node and itself whose force tells which element it is (its index as
/// the first component) and how often it was evaluated; it can be told to fail or to return
/// a non-finite force.
class TaggedElement final : public element::Element {
public:
  enum class Outcome { ok, fails, not_finite };
  TaggedElement(int node, int tag, Outcome outcome) : node_{node}, tag_(tag), outcome_(outcome) {}

  std::span<const int> nodes() const override { return node_; }
  bool evaluate(std::span<const element::NodeConfiguration> configuration, Eigen::VectorXd& force,
                Eigen::MatrixXd& tangent, std::string& failure) override {
    ++evaluations_;
    force = Eigen::VectorXd::Zero(6);
    force[0] = tag_;
    force[1] = configuration[0].position.x();
    tangent = Eigen::MatrixXd::Identity(6, 6) * tag_;
    if (outcome_ == Outcome::fails) {
      failure = "element " + std::to_string(tag_) + " failed";
      return false;
    }
    if (outcome_ == Outcome::not_finite)
      force[2] = std::numeric_limits<double>::quiet_NaN();
    return true;
  }
  void commit() override {}
  void revert_to_committed() override {}
  element::ElementEnergy energy() const override { return {}; }
  void copy_state_from(const element::Element& other) override {
    element::copy_element_value(*this, other);
  }
  int evaluations() const { return evaluations_; }

private:
  std::array<int, 1> node_;
  int tag_;
  Outcome outcome_;
  int evaluations_ = 0;
};

struct TaggedModel {
  Model model;
  std::vector<TaggedElement*> elements;
};

/// `count` tagged elements on 3 nodes (at x = 0, 1, 2 mm), element e on node e % 3.
TaggedModel tagged_model(int count,
                         const std::vector<std::pair<int, TaggedElement::Outcome>>& outcomes = {}) {
  TaggedModel tagged;
  for (int node = 0; node < 3; ++node)
    tagged.model.add_node(element::Vector3(node, 0.0, 0.0));
  for (int e = 0; e < count; ++e) {
    TaggedElement::Outcome outcome = TaggedElement::Outcome::ok;
    for (const auto& [element, told] : outcomes)
      if (element == e)
        outcome = told;
    tagged.elements.push_back(
        &tagged.model.add_element(std::make_unique<TaggedElement>(e % 3, e, outcome)));
  }
  return tagged;
}

TEST(ElementEvaluations, EveryElementOnceIntoItsOwnBuffersForAnyThreadCount) {
  for (const int threads : {1, 2, 3, 8}) {
    TaggedModel tagged = tagged_model(37); // not a multiple of the chunk or thread counts
    ElementEvaluations evaluations(threads);
    EXPECT_EQ(evaluations.threads(), threads);
    std::vector<element::NodeConfiguration> nodes(3);
    for (int loop = 0; loop < 50; ++loop) {
      for (int node = 0; node < 3; ++node)
        nodes[node].position.x() = node + 10.0 * loop;
      std::string failure;
      ASSERT_TRUE(evaluations.evaluate(tagged.model, nodes, true, failure)) << failure;
      for (std::size_t e = 0; e < tagged.elements.size(); ++e) {
        ASSERT_EQ(evaluations.force(e)[0], static_cast<double>(e)) << threads << " threads";
        ASSERT_EQ(evaluations.force(e)[1], static_cast<double>(e % 3) + 10.0 * loop);
        ASSERT_EQ(evaluations.tangent(e)(5, 5), static_cast<double>(e));
      }
    }
    for (const TaggedElement* element : tagged.elements)
      EXPECT_EQ(element->evaluations(), 50) << threads << " threads";
  }
}

TEST(ElementEvaluations, ReportsTheFirstFailingElementInElementOrder) {
  using Outcome = TaggedElement::Outcome;
  for (const int threads : {1, 2, 4}) {
    // element 30 fails too: on more threads it may fail first in time, never in the report
    TaggedModel tagged = tagged_model(40, {{30, Outcome::fails}, {11, Outcome::fails}});
    ElementEvaluations evaluations(threads);
    std::vector<element::NodeConfiguration> nodes(3);
    std::string failure;
    EXPECT_FALSE(evaluations.evaluate(tagged.model, nodes, true, failure));
    EXPECT_EQ(failure, "element 11 failed") << threads << " threads";
    if (threads == 1) { // one thread stops at the failure
      EXPECT_EQ(tagged.elements[12]->evaluations(), 0);
    }

    TaggedModel not_finite = tagged_model(9, {{7, Outcome::not_finite}});
    failure.clear();
    EXPECT_FALSE(evaluations.evaluate(not_finite.model, nodes, false, failure));
    EXPECT_EQ(failure, "element 7 returned a non-finite force or tangent");
  }
}

TEST(ElementEvaluations, ElementsLeftOutAreNotEvaluated) {
  for (const int threads : {1, 3}) {
    TaggedModel tagged = tagged_model(10, {{4, TaggedElement::Outcome::fails}});
    std::vector<bool> include(10, true);
    include[4] = include[7] = false; // the failing element among those left out
    ElementEvaluations evaluations(threads);
    std::vector<element::NodeConfiguration> nodes(3);
    std::string failure;
    EXPECT_TRUE(evaluations.evaluate(tagged.model, nodes, true, failure, &include)) << failure;
    for (int e = 0; e < 10; ++e)
      EXPECT_EQ(tagged.elements[e]->evaluations(), include[e] ? 1 : 0) << "element " << e;
  }
}

TEST(ElementEvaluations, RefusesAThreadCountBelowOne) {
  EXPECT_THROW(ElementEvaluations(0), std::invalid_argument);
}

} // namespace
} // namespace brb::model
