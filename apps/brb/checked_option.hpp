// Numeric CLI options with a checked range. A physical value (a step in mm,
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

/// Registers `--threads N` (a whole number 1 to 256, stored into `threads`): the threads that
/// evaluate a brace's elements (NewtonSettings::element_threads), whose count does not change
/// the results. `description` says what the command's runs gain from it.
inline CLI::Option* add_element_threads_option(CLI::App& command, int& threads,
                                               const std::string& description) {
  return command.add_option("--threads", threads, description)
      ->type_name("N")
      ->check(CLI::Range(1, 256));
}

} // namespace brb::cli
