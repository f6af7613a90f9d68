#include "progress_line.hpp"

#include "checked_option.hpp"

#include <iomanip>
#include <ios>
#include <sstream>
#include <utility>

namespace brb::cli {

ProgressLine::ProgressLine(std::ostream& out, std::string label, std::size_t steps, double interval,
                           std::mutex* lock, std::string counted)
    : out_(&out), label_(std::move(label)), counted_(std::move(counted)), steps_(steps),
      interval_(interval), lock_(lock), start_(std::chrono::steady_clock::now()), last_(start_) {}

void ProgressLine::operator()(const analysis::CyclicStep& step) {
  substeps_ += step.substeps;
  const auto now = std::chrono::steady_clock::now();
  const bool last = static_cast<std::size_t>(step.step) >= steps_;
  if (!last && std::chrono::duration<double>(now - last_).count() < interval_)
    return;
  last_ = now;
  const double done = steps_ > 0 ? 100.0 * step.step / static_cast<double>(steps_) : 100.0;
  std::ostringstream line; // composed first: one write per line when runs share the stream
  line << label_ << "step " << step.step << " of " << steps_ << " (" << std::fixed
       << std::setprecision(1) << done << " %), deformation " << std::setprecision(3)
       << step.deformation << " mm, force " << std::setprecision(0) << step.force << " N, "
       << substeps_ << " " << counted_ << ", " << std::setprecision(1)
       << std::chrono::duration<double>(now - start_).count() << " s\n";
  const std::unique_lock guard = lock_ ? std::unique_lock(*lock_) : std::unique_lock<std::mutex>();
  *out_ << line.str() << std::flush;
}

void add_progress_option(CLI::App& command, std::optional<double>& interval,
                         const std::string& description) {
  add_checked_number_option(
      command, "--progress", interval, [](double seconds) { return seconds >= 0.0; },
      "must be a number of seconds >= 0", "SECONDS", description);
}

} // namespace brb::cli
