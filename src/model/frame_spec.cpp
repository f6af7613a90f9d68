#include "brb/model/frame_spec.hpp"

#include <stdexcept>
#include <string>

namespace brb::model {

const FrameNodeSpec& FrameSpec::node(int id) const {
  for (const auto& candidate : nodes) {
    if (candidate.id == id)
      return candidate;
  }
  throw std::out_of_range("frame model: no node with id " + std::to_string(id));
}

void FrameSpec::set_brace_core_elements(int count) {
  for (FrameElementSpec& element : elements) {
    if (auto* brace = std::get_if<BraceElementSpec>(&element.kind))
      brace->brace.core_elements = count;
  }
}

double FrameSpec::element_length(const FrameElementSpec& element) const {
  return (node(element.nodes[1]).coordinates - node(element.nodes[0]).coordinates).norm();
}

} // namespace brb::model
