#include "brb/element/element.hpp"

#include <stdexcept>
#include <typeinfo>

namespace brb::element {

void Element::save_state(io::StateWriter& /*out*/) const {
  throw std::logic_error(std::string("checkpoint: this element (") + typeid(*this).name() +
                         ") does not save its state");
}

void Element::load_state(io::StateReader& /*in*/) {
  throw std::logic_error(std::string("checkpoint: this element (") + typeid(*this).name() +
                         ") does not read a state");
}

} // namespace brb::element
