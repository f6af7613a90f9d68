// One way to register a numeric CLI option whose value has a physical range (a step in mm,
// a fraction of the gross work, an interval in seconds): the value must be finite and pass
// `accept`, otherwise the parse fails with "<name>: <requirement>" and a non-zero exit.
#pragma once

#include <CLI/CLI.hpp>

#include <cmath>
#include <string>

namespace brb::cli {

/// Registers `name VALUE_NAME` on `command`, storing a parsed value into `target` (a double,
/// or a std::optional<double> left empty when the option is not given) when it is finite and
/// `accept(value)` holds; otherwise CLI11 reports `requirement` (e.g. "must be a number in
/// [0, 1)") for the option.
template <class Target, class Accept>
CLI::Option* add_checked_number_option(CLI::App& command, const std::string& name, Target& target,
                                       Accept accept, const std::string& requirement,
                                       const std::string& value_name,
                                       const std::string& description) {
  return command
      .add_option_function<double>(
          name,
          [&target, accept, name, requirement](const double& value) {
            if (!(std::isfinite(value) && accept(value)))
              throw CLI::ValidationError(name, requirement);
            target = value;
          },
          description)
      ->type_name(value_name);
}

} // namespace brb::cli
