// The element loop of an assembly: every element of a model (or those asked) evaluated at a
// configuration of the nodes, each into its own force vector and tangent, on one thread or
// on a team of threads (model/thread_team.hpp). The assemblers (Assembler, StaticAnalysis)
// then gather the results in element order, so the sums, and with them every result of a
// run, are bitwise the same for any thread count. Elements are values with no state shared
// between them (an element's evaluate writes only its own trial state), which is what lets
// two of them evaluate at once.
//
// Why threads here: a restrained core at 4x its default discretisation (48 core elements,
// their casing and some 200 contact links) spends most of a run in the elements (the fiber
// laws, the local beams), one assembly at a time; Newton's path cannot be split, the
// elements of one assembly can.
#pragma once

#include "brb/element/element.hpp"
#include "brb/model/model.hpp"
#include "brb/model/thread_team.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace brb::model {

class ElementEvaluations {
public:
  /// `threads` >= 1 (std::invalid_argument otherwise).
  explicit ElementEvaluations(int threads = 1);

  int threads() const { return team_.threads(); }

  /// Evaluates the elements of `model` (all, or those with include[e] true) at `nodes` (one
  /// configuration per model node). Returns false with the reason of the first element, in
  /// element order, that cannot evaluate or returns a non-finite force (or tangent, when
  /// `with_tangent`). On one thread the loop stops at that element; on more, the others
  /// have been evaluated too, which changes nothing but their trial states (a failed
  /// assembly is retried or reverted by the caller).
  bool evaluate(const Model& model, std::span<const element::NodeConfiguration> nodes,
                bool with_tangent, std::string& failure,
                const std::vector<bool>* include = nullptr);

  /// Force (6 per node, in the order of the element's nodes()) and tangent of element `e`
  /// from the last evaluate() that included it.
  const Eigen::VectorXd& force(std::size_t e) const { return results_[e].force; }
  const Eigen::MatrixXd& tangent(std::size_t e) const { return results_[e].tangent; }

private:
  struct Result {
    std::vector<element::NodeConfiguration> nodes; ///< the element's nodes' configurations
    Eigen::VectorXd force;
    Eigen::MatrixXd tangent;
    std::string failure; ///< empty when the evaluation succeeded
  };
  void evaluate_one(element::Element& element, std::size_t e,
                    std::span<const element::NodeConfiguration> nodes, bool with_tangent);

  std::vector<Result> results_;
  ThreadTeam team_;
};

} // namespace brb::model
