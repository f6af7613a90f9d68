// An incremental dynamic analysis (Vamvatsikos & Cornell 2002) of a frame over a suite of
// ground motions: the intensity measure of each record, one nonlinear time-history run per
// (record, intensity) with the record scaled to that intensity, and the hunt-and-fill trace
// of each record's curve. A run depends only on its record and intensity (each builds its
// own frame from the specification), so runs may go in any order, on any thread or process,
// and give the same numbers: the basis of determinism, the journal and resumption.
#pragma once

#include "brb/frame/frame_builder.hpp"
#include "brb/ida/hunt_and_fill.hpp"
#include "brb/ida/ida_point.hpp"
#include "brb/io/suite_input.hpp"
#include "brb/model/frame_spec.hpp"

#include <nlohmann/json.hpp>

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace brb::ida {

/// Sa(T1, zeta): the pseudo-spectral acceleration of the linear oscillator of period T1
/// (exact piecewise-linear solution, analysis/sdof_exact.hpp); pga: peak ground acceleration.
enum class IntensityMeasure { sa_t1, pga };

struct IdaSettings {
  IntensityMeasure measure = IntensityMeasure::sa_t1;
  std::optional<double> period; ///< s; default T1 of the frame's modal analysis
  double damping_ratio = 0.05;  ///< of the Sa oscillator
  HuntFillSettings trace{0.2, 0.2, 0.2, 0.05, 12, 0.0};
  std::optional<double> drift_limit;   ///< default: the frame file's (10 % unless it says)
  std::optional<double> mce_intensity; ///< S_MT, g: the collapse margin ratio is reported
  frame::BraceOverride braces = frame::BraceOverride::none;
};

class IdaStudy {
public:
  /// Reads nothing: the frame specification and suite are given. Computes T1 (gravity and
  /// modal analysis of the frame as built) unless the settings give the period, and each
  /// record's intensity. Throws std::runtime_error when gravity does not converge and
  /// std::invalid_argument when a record has zero intensity.
  IdaStudy(model::FrameSpec spec, std::string model_source, io::GroundMotionSuite suite,
           IdaSettings settings);

  const IdaSettings& settings() const { return settings_; }
  const io::GroundMotionSuite& suite() const { return suite_; }
  std::size_t record_count() const { return suite_.records.size(); }
  double period() const { return period_; }          ///< s (Sa: the oscillator's; pga: T1)
  double record_intensity(std::size_t record) const; ///< g, the record as normalised
  double drift_limit() const { return run_options_.drift_limit; }
  const std::vector<std::string>& story_names() const { return story_names_; }
  /// "Sa(T1 = 0.727 s, 5 %)" or "PGA"; intensities are in g.
  std::string measure_label() const;

  /// The journal header: what the results depend on (model and suite content digests,
  /// settings, period, record intensities).
  nlohmann::json header(const std::string& model_text, const std::string& suite_text) const;

  /// One time-history run of `record` scaled to `intensity` (g). Never throws for a failed
  /// analysis: an exception inside the solver counts as numerical collapse with its message.
  IdaPoint run(std::size_t record, double intensity) const;

  /// Traces `record`'s curve by hunt-and-fill. A run whose intensity is in `known` (points of
  /// this record from a journal) is taken from there; every new point is passed to `finished`
  /// (e.g. to append it to the journal) before the trace goes on.
  std::vector<IdaPoint> trace(std::size_t record, const std::map<double, IdaPoint>& known,
                              const std::function<void(const IdaPoint&)>& finished) const;

private:
  model::FrameSpec spec_;
  std::string model_source_;
  io::GroundMotionSuite suite_;
  IdaSettings settings_;
  frame::FrameRunOptions run_options_;
  double period_ = 0.0;
  std::vector<double> record_intensity_;
  std::vector<std::string> story_names_;
};

/// The hunt-and-fill settings as JSON (journal header, summary.json).
nlohmann::json to_json(const HuntFillSettings& trace);

/// FNV-1a 64-bit digest of a text as 16 hex digits: identifies input files in the journal.
std::string content_digest(std::string_view text);

} // namespace brb::ida
