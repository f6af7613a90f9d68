#include "checkpoint_option.hpp"
#include "checked_option.hpp"

namespace brb::cli {

void add_checkpoint_interval_option(CLI::App& command, double& interval) {
  add_checked_number_option(
      command, "--checkpoint-every", interval, [](double seconds) { return seconds > 0.0; },
      "must be a number of seconds > 0", "SECONDS",
      "Wall time between two checkpoint writes, s (default 600); each write replaces the "
      "last one atomically");
}

} // namespace brb::cli
