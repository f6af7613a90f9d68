// The error every material (and later section/element) parameter check throws.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace brb {

/// An invalid model parameter. `field` is the parameter's key as users write it in
/// input files (e.g. "fy", "chaboche[1].gamma"), so the io layer can name the file and
/// JSON path; `what()` says what was expected.
class ParameterError : public std::invalid_argument {
public:
  ParameterError(std::string field, const std::string& expected)
      : std::invalid_argument(expected), field_(std::move(field)) {}
  const std::string& field() const { return field_; }

private:
  std::string field_;
};

} // namespace brb
