#include "brb/frame/frame_run.hpp"

#include "brb/analysis/explicit_analysis.hpp"
#include "brb/analysis/modal_analysis.hpp"
#include "brb/model/dof_map.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace brb::frame {

namespace {

/// The largest peak story drift ratio recorded so far (0 before any story is).
double peak_drift_so_far(const FrameRunResult& result) {
  return result.max_drift.empty()
             ? 0.0
             : *std::max_element(result.max_drift.begin(), result.max_drift.end());
}

constexpr double kStandardGravity = 9806.65; // mm/s^2
/// Largest translational mass the explicit solver's mass scaling may add (fraction).
constexpr double kExplicitAddedMassFraction = 0.05;

using analysis::GroundAcceleration;
using model::kDofPerNode;

/// The implicit or explicit solver behind one interface (one virtual call per step).
class DynamicSolver {
public:
  virtual ~DynamicSolver() = default;
  virtual analysis::TransientStepReport step(double dt) = 0;
  virtual Eigen::VectorXd displacement() const = 0;
  virtual Eigen::VectorXd acceleration() const = 0;
  /// Ground acceleration (global vector, mm/s^2) at the committed time.
  virtual Eigen::Vector3d ground_acceleration() const = 0;
  virtual const Eigen::VectorXd& internal_force() const = 0;
  virtual const analysis::TransientEnergy& energy() const = 0;
  virtual const std::vector<analysis::FallbackRecord>& fallbacks() const = 0;
};

/// The queries both solvers answer alike, forwarded to the analysis.
template <class Analysis> class ForwardingSolver : public DynamicSolver {
public:
  explicit ForwardingSolver(Analysis& analysis) : analysis_(analysis) {}
  Eigen::VectorXd displacement() const override { return analysis_.displacement(); }
  Eigen::VectorXd acceleration() const override { return analysis_.acceleration(); }
  Eigen::Vector3d ground_acceleration() const override { return analysis_.ground_acceleration(); }
  const Eigen::VectorXd& internal_force() const override { return analysis_.internal_force(); }
  const analysis::TransientEnergy& energy() const override { return analysis_.energy(); }
  const std::vector<analysis::FallbackRecord>& fallbacks() const override {
    return analysis_.fallbacks();
  }

protected:
  Analysis& analysis_;
};

class ImplicitSolver final : public ForwardingSolver<analysis::TransientAnalysis> {
public:
  using ForwardingSolver::ForwardingSolver;
  analysis::TransientStepReport step(double dt) override { return analysis_.step(dt); }
};

/// The explicit solver: one call advances to the next output instant through as many
/// stable steps as needed.
class ExplicitSolver final : public ForwardingSolver<analysis::ExplicitAnalysis> {
public:
  using ForwardingSolver::ForwardingSolver;
  analysis::TransientStepReport step(double dt) override {
    const analysis::ExplicitStepReport run = analysis_.run_to(analysis_.time() + dt);
    analysis::TransientStepReport report;
    report.converged = run.completed;
    report.substeps = run.steps;
    report.failure = run.failure;
    return report;
  }
};

/// Follows what the recorders and the summary need, step by step.
class Recorder {
public:
  Recorder(const FrameModel& frame, const FrameRunOptions& options, FrameRunResult& result)
      : frame_(frame), options_(options), result_(result),
        computed_(computed_histories(options, frame)) {
    result_.max_drift.assign(frame.stories.size(), 0.0);
    result_.residual_drift.assign(frame.stories.size(), 0.0);
    result_.peak_floor_acceleration.assign(frame.floors.size(), 0.0);
    for (const BraceReference& brace : frame.braces) {
      BraceSummary summary;
      summary.id = brace.id;
      summary.fidelity = brace.fidelity;
      result_.braces.push_back(summary);
      last_brace_state_.push_back({0.0, 0.0});
    }
    const RecorderRequest& asked = computed_;
    if (asked.drifts) {
      History& drifts = result_.histories["drifts"];
      drifts.columns.push_back("time");
      for (const StoryReference& story : frame.stories) {
        drifts.columns.push_back("drift_x_" + story.name);
        if (frame.dimension == 3)
          drifts.columns.push_back("drift_y_" + story.name);
      }
    }
    if (asked.floor_accelerations) {
      History& accelerations = result_.histories["floor_accelerations"];
      accelerations.columns.push_back("time");
      for (const FloorReference& floor : frame.floors) {
        accelerations.columns.push_back("accel_x_" + floor.name + "_g");
        if (frame.dimension == 3)
          accelerations.columns.push_back("accel_y_" + floor.name + "_g");
      }
    }
    if (asked.base_shear) {
      History& shear = result_.histories["base_shear"];
      shear.columns = {"time", "base_shear_x"};
      if (frame.dimension == 3)
        shear.columns.push_back("base_shear_y");
    }
    if (asked.energy) {
      result_.histories["energy"].columns = {
          "time",   "input",      "static_work",        "kinetic", "damping",
          "stored", "dissipated", "integration_misfit", "error"};
    }
    for (const int id : computed_.braces) {
      const auto found = std::find_if(frame.braces.begin(), frame.braces.end(),
                                      [id](const BraceReference& b) { return b.id == id; });
      if (found == frame.braces.end())
        throw std::invalid_argument("brace histories asked for element " + std::to_string(id) +
                                    ", which is not a brb element");
      recorded_braces_.push_back(static_cast<int>(found - frame.braces.begin()));
    }
    if (!recorded_braces_.empty()) {
      History& braces = result_.histories["braces"];
      braces.columns = {"time",           "brace",          "force",
                        "deformation",    "core_strain",    "cid",
                        "steel_damage",   "mortar_damage",  "core_fracture",
                        "casing_failure", "global_buckling"};
    }
  }

  /// Observes a converged state at `time`; returns the largest story drift ratio.
  double observe(double time, const DynamicSolver& solver) {
    const Eigen::VectorXd displacement = solver.displacement();
    double largest_drift = 0.0;
    std::vector<double> drift_row{time};
    for (std::size_t s = 0; s < frame_.stories.size(); ++s) {
      const StoryReference& story = frame_.stories[s];
      const Eigen::Vector3d relative = displacement.segment<3>(kDofPerNode * story.top) -
                                       displacement.segment<3>(kDofPerNode * story.bottom);
      const double drift_x = relative.x() / story.height, drift_y = relative.y() / story.height;
      const double drift = std::hypot(drift_x, drift_y);
      result_.max_drift[s] = std::max(result_.max_drift[s], drift);
      result_.residual_drift[s] = drift;
      largest_drift = std::max(largest_drift, drift);
      drift_row.push_back(drift_x);
      if (frame_.dimension == 3)
        drift_row.push_back(drift_y);
    }
    if (computed_.drifts)
      result_.histories["drifts"].rows.push_back(std::move(drift_row));

    if (!frame_.floors.empty()) {
      const Eigen::VectorXd acceleration = solver.acceleration();
      const Eigen::Vector3d ground = solver.ground_acceleration();
      std::vector<double> row{time};
      for (std::size_t f = 0; f < frame_.floors.size(); ++f) {
        const Eigen::Vector3d absolute =
            (acceleration.segment<3>(kDofPerNode * frame_.floors[f].node) + ground) /
            kStandardGravity;
        result_.peak_floor_acceleration[f] =
            std::max(result_.peak_floor_acceleration[f], std::hypot(absolute.x(), absolute.y()));
        row.push_back(absolute.x());
        if (frame_.dimension == 3)
          row.push_back(absolute.y());
      }
      if (computed_.floor_accelerations)
        result_.histories["floor_accelerations"].rows.push_back(std::move(row));
    }

    const Eigen::VectorXd& force = solver.internal_force();
    Eigen::Vector2d shear = Eigen::Vector2d::Zero();
    for (const int node : frame_.support_nodes)
      shear += force.segment<2>(kDofPerNode * node);
    // the base shear is the sum of the support reactions (minus the elements' forces on them)
    result_.peak_base_shear = std::max(result_.peak_base_shear, shear.norm());
    if (computed_.base_shear) {
      std::vector<double> row{time, -shear.x()};
      if (frame_.dimension == 3)
        row.push_back(-shear.y());
      result_.histories["base_shear"].rows.push_back(std::move(row));
    }

    const analysis::TransientEnergy& energy = solver.energy();
    if (computed_.energy) {
      result_.histories["energy"].rows.push_back(
          {time, energy.input, energy.static_work, energy.kinetic, energy.damping, energy.stored,
           energy.dissipated, energy.integration_misfit, energy.absolute_error()});
    }

    for (std::size_t b = 0; b < frame_.braces.size(); ++b)
      observe_brace(b);
    for (const int b : recorded_braces_) {
      const BraceReference& brace = frame_.braces[b];
      const BraceSummary& summary = result_.braces[b];
      double steel = 0.0, mortar = 0.0;
      if (brace.full) {
        steel = brace.full->indicators().max_steel_damage;
        mortar = brace.full->indicators().max_mortar_damage;
      } else {
        steel = brace.truss->damage();
      }
      result_.histories["braces"].rows.push_back(
          {time, static_cast<double>(brace.id), brace.axial_force(), brace.deformation(),
           brace.core_strain(), summary.cumulative_inelastic_deformation, steel, mortar,
           summary.core_fracture ? 1.0 : 0.0, summary.casing_failure ? 1.0 : 0.0,
           summary.global_buckling ? 1.0 : 0.0});
    }
    return largest_drift;
  }

  /// Drops the histories computed but not asked (requested_recorders off).
  void drop_unrequested() {
    const RecorderRequest& asked = options_.recorders;
    const std::pair<const char*, bool> kinds[] = {
        {"drifts", asked.drifts},
        {"floor_accelerations", asked.floor_accelerations},
        {"base_shear", asked.base_shear},
        {"energy", asked.energy}};
    for (const auto& [name, wanted] : kinds) {
      if (!wanted)
        result_.histories.erase(name);
    }
    if (asked.braces.size() == computed_.braces.size())
      return;
    const auto found = result_.histories.find("braces");
    if (found == result_.histories.end())
      return;
    if (asked.braces.empty()) {
      result_.histories.erase(found);
      return;
    }
    // keep the rows of the asked braces, in the order they were recorded
    std::vector<std::vector<double>> kept;
    for (std::vector<double>& row : found->second.rows) {
      const int id = static_cast<int>(row[1]);
      if (std::find(asked.braces.begin(), asked.braces.end(), id) != asked.braces.end())
        kept.push_back(std::move(row));
    }
    found->second.rows = std::move(kept);
  }

private:
  /// What the recorder computes: what was asked, or everything when the requested-recorders
  /// skip is off (every history, every brace in the order asked first, then the others).
  static RecorderRequest computed_histories(const FrameRunOptions& options,
                                            const FrameModel& frame) {
    RecorderRequest computed = options.recorders;
    if (options.skips.requested_recorders)
      return computed;
    computed.drifts = computed.floor_accelerations = computed.base_shear = computed.energy = true;
    for (const BraceReference& brace : frame.braces) {
      if (std::find(computed.braces.begin(), computed.braces.end(), brace.id) ==
          computed.braces.end())
        computed.braces.push_back(brace.id);
    }
    return computed;
  }

  void observe_brace(std::size_t b) {
    const BraceReference& brace = frame_.braces[b];
    BraceSummary& summary = result_.braces[b];
    const double force = brace.axial_force();
    const double deformation = brace.deformation();
    summary.max_tension = std::max(summary.max_tension, force);
    summary.max_compression = std::max(summary.max_compression, -force);
    summary.max_core_strain = std::max(summary.max_core_strain, std::abs(brace.core_strain()));
    if (brace.full) {
      const analysis::BraceIndicators& indicators = brace.full->indicators();
      summary.cumulative_inelastic_deformation = indicators.cumulative_inelastic_deformation;
      summary.core_fracture = indicators.core_fracture;
      summary.casing_failure = indicators.casing_failure;
      summary.global_buckling = indicators.global_buckling;
    } else {
      auto& [last_force, last_deformation] = last_brace_state_[b];
      summary.cumulative_inelastic_deformation += analysis::inelastic_deformation_increment(
          deformation - last_deformation, force - last_force, brace.yield_force,
          brace.yield_deformation);
      last_force = force;
      last_deformation = deformation;
      summary.core_fracture = brace.truss->damage() >= analysis::kFractureDamage;
    }
  }

  const FrameModel& frame_;
  const FrameRunOptions& options_;
  FrameRunResult& result_;
  std::vector<std::pair<double, double>> last_brace_state_; // (force, deformation) per brace
  RecorderRequest computed_;
  std::vector<int> recorded_braces_;
};

/// The damping of the options on the analysis (after gravity), with the modal periods.
analysis::DampingSpec damping_spec(const FrameModel& frame, const FrameRunOptions& options,
                                   const std::vector<analysis::Mode>& modes) {
  analysis::DampingSpec spec;
  const DampingOptions& damping = options.damping;
  const auto frequency = [&](int mode) {
    if (mode < 1 || mode > static_cast<int>(modes.size()))
      throw std::invalid_argument("damping: mode " + std::to_string(mode) +
                                  " asked, the model has " + std::to_string(modes.size()) +
                                  " modes with mass");
    return modes[mode - 1].circular_frequency;
  };
  switch (damping.kind) {
  case DampingOptions::Kind::none:
    break;
  case DampingOptions::Kind::rayleigh: {
    const auto [a0, a1] = analysis::rayleigh_coefficients(
        frequency(damping.mode_i), damping.ratio_i, frequency(damping.mode_j), damping.ratio_j);
    spec.mass_factor = a0;
    spec.stiffness_factor = a1;
    if (damping.exclude_braces)
      spec.include_in_stiffness_damping = frame.in_stiffness_damping;
    break;
  }
  case DampingOptions::Kind::modal:
    spec.modal_ratios.assign(
        std::min<std::size_t>(static_cast<std::size_t>(damping.modal_modes), modes.size()),
        damping.modal_ratio);
    break;
  }
  return spec;
}

/// The explicit step that keeps the translational mass added by selective mass scaling
/// below `fraction` of the model's translational mass. ExplicitAnalysis gives each massless
/// equation m_i = R_i (dt^2 + a1 dt), R_i the row sum of |K0|, a1 the stiffness part of the
/// damping: the step solves dt^2 + a1 dt = fraction M / sum R_i over the massless
/// translations. (The added mass of a massless floor-level DOF, a beam's mid-span node, joins
/// the storey's inertia and slows the frame down.)
double explicit_step_for_mass_scaling(analysis::TransientAnalysis& analysis, double fraction,
                                      double stiffness_damping) {
  const Eigen::SparseMatrix<double> tangent = analysis.tangent();
  const Eigen::SparseMatrix<double>& mass = analysis.mass();
  const model::DofMap& map = analysis.dof_map();
  Eigen::VectorXd row_sum = Eigen::VectorXd::Zero(tangent.rows());
  for (int column = 0; column < tangent.outerSize(); ++column) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(tangent, column); it; ++it)
      row_sum[it.row()] += std::abs(it.value());
  }
  double translational_mass = 0.0, massless_stiffness = 0.0;
  for (int dof = 0; dof < map.full_dof_count(); ++dof) {
    const int equation = map.independent_equation(dof);
    if (equation < 0 || dof % kDofPerNode >= 3)
      continue;
    const double m = mass.coeff(equation, equation);
    if (m > 0.0)
      translational_mass += m;
    else
      massless_stiffness += row_sum[equation];
  }
  if (massless_stiffness == 0.0)
    return std::numeric_limits<double>::infinity();
  const double target = fraction * translational_mass / massless_stiffness;
  return 0.5 *
         (-stiffness_damping + std::sqrt(stiffness_damping * stiffness_damping + 4.0 * target));
}

/// The implicit analysis of the options (Newmark or HHT); the explicit solver starts from its
/// gravity state.
analysis::TransientAnalysis implicit_analysis_of(FrameModel& frame,
                                                 const FrameRunOptions& options) {
  analysis::TransientSettings settings;
  settings.integrator = options.integrator == Integrator::hht ? analysis::TimeIntegrator::hht
                                                              : analysis::TimeIntegrator::newmark;
  settings.hht_alpha = options.integrator == Integrator::hht ? options.hht_alpha : 0.0;
  return analysis::TransientAnalysis(*frame.model,
                                     model::DofMap::build(*frame.model, frame.dimension), settings);
}

} // namespace

std::vector<double> gravity_periods(FrameModel& frame, const FrameRunOptions& options, int modes) {
  analysis::TransientAnalysis analysis = implicit_analysis_of(frame, options);
  const analysis::TransientStepReport gravity =
      analysis.apply_static_load(frame.gravity_load, std::max(frame.gravity_steps, 1));
  if (!gravity.converged)
    throw std::runtime_error("gravity load did not converge: " + gravity.failure);
  std::vector<double> periods;
  for (const analysis::Mode& mode :
       analysis::modal_analysis(analysis.tangent(), analysis.mass(), analysis.dof_map(), modes))
    periods.push_back(mode.period);
  return periods;
}

FrameRunResult run_time_history(FrameModel& frame,
                                const std::vector<GroundAcceleration>& components,
                                const FrameRunOptions& options) {
  if (components.empty())
    throw std::invalid_argument("a time-history analysis needs a ground motion");
  if (components.size() > options.directions.size())
    throw std::invalid_argument("more ground-motion components than directions");
  FrameRunResult result;
  double record_duration = 0.0;
  for (const GroundAcceleration& component : components) {
    record_duration = std::max(
        record_duration, component.dt * static_cast<double>(component.acceleration.size() - 1));
  }
  const double dt = options.dt > 0.0 ? options.dt : components.front().dt;
  result.duration = record_duration + options.free_vibration;

  analysis::TransientAnalysis analysis = implicit_analysis_of(frame, options);

  // Gravity, held during the dynamic run.
  const analysis::TransientStepReport gravity =
      analysis.apply_static_load(frame.gravity_load, std::max(frame.gravity_steps, 1));
  result.gravity_converged = gravity.converged;
  if (!gravity.converged) {
    // no step was taken: the drifts stay empty (not zero: nothing was computed)
    result.stop_reason = "gravity load did not converge: " + gravity.failure;
    return result;
  }

  const std::vector<analysis::Mode> modes = analysis::modal_analysis(
      analysis.tangent(), analysis.mass(), analysis.dof_map(),
      std::max({options.damping.mode_i, options.damping.mode_j, options.damping.modal_modes, 3}));
  for (const analysis::Mode& mode : modes)
    result.periods.push_back(mode.period);
  const analysis::DampingSpec damping = damping_spec(frame, options, modes);
  std::vector<GroundAcceleration> ground;
  for (std::size_t c = 0; c < components.size(); ++c) {
    ground.push_back(components[c]);
    ground.back().direction = options.directions[c];
  }

  // The implicit solver carries on from its gravity state; the explicit one starts from it
  // (the elements hold the committed gravity state) with the gravity load held.
  std::unique_ptr<analysis::ExplicitAnalysis> explicit_analysis;
  std::unique_ptr<DynamicSolver> solver;
  if (options.integrator == Integrator::explicit_central_difference) {
    if (!damping.modal_ratios.empty())
      throw std::invalid_argument("modal damping is not available with the explicit integrator: "
                                  "use Rayleigh damping");
    // The step: a substep of the output step, short enough that mass scaling adds at most
    // kExplicitAddedMassFraction of the mass, and stable (the solver refuses an unstable one).
    analysis::ExplicitSettings settings;
    settings.time_step = analysis::record_substep(
        dt, explicit_step_for_mass_scaling(analysis, kExplicitAddedMassFraction,
                                           damping.stiffness_factor));
    const auto make_explicit = [&](const analysis::ExplicitSettings& explicit_settings) {
      auto made = std::make_unique<analysis::ExplicitAnalysis>(
          *frame.model, model::DofMap::build(*frame.model, frame.dimension), explicit_settings);
      made->initialise_static(analysis.nodes(), frame.gravity_load);
      made->set_damping(damping);
      for (const GroundAcceleration& component : ground)
        made->add_ground_acceleration(component);
      return made;
    };
    for (int attempt = 0; attempt < 20; ++attempt) {
      analysis::ExplicitSettings probe = settings;
      probe.refuse_unstable_step = false;
      const double stable = make_explicit(probe)->stable_time_step();
      if (settings.time_step <= stable)
        break;
      settings.time_step = analysis::record_substep(dt, stable);
    }
    explicit_analysis = make_explicit(settings);
    explicit_analysis->prepare();
    result.explicit_time_step = explicit_analysis->time_step();
    result.added_mass_fraction = explicit_analysis->mass_scaling().translational_fraction();
    solver = std::make_unique<ExplicitSolver>(*explicit_analysis);
  } else {
    analysis.set_damping(damping);
    for (GroundAcceleration& component : ground)
      analysis.add_ground_acceleration(std::move(component));
    solver = std::make_unique<ImplicitSolver>(analysis);
  }

  Recorder recorder(frame, options, result);
  recorder.observe(0.0, *solver);

  const auto step_count = static_cast<long>(std::ceil(result.duration / dt - 1e-9));
  result.converged = true;
  for (long n = 1; n <= step_count; ++n) {
    const auto step_started = std::chrono::steady_clock::now();
    const double target = std::min(static_cast<double>(n) * dt, result.duration);
    const analysis::TransientStepReport report = solver->step(target - result.end_time);
    if (!report.converged) {
      result.converged = false;
      std::ostringstream reason;
      reason << "step to t = " << target
             << " s did not converge after every fallback: " << report.failure;
      result.stop_reason = reason.str();
      break;
    }
    result.end_time = target;
    ++result.steps;
    const double drift = recorder.observe(target, *solver);
    if (options.progress)
      options.progress({target, result.duration, n, step_count, peak_drift_so_far(result)});
    if (options.record_step_wall_times) {
      result.step_wall_times.push_back(
          std::chrono::duration<double>(std::chrono::steady_clock::now() - step_started).count());
    }
    if (drift > options.drift_limit) {
      result.collapsed = true;
      std::ostringstream reason;
      reason << "collapse: a story drift ratio of " << drift << " exceeded the limit "
             << options.drift_limit << " at t = " << target << " s";
      result.stop_reason = reason.str();
      break;
    }
  }
  recorder.drop_unrequested();
  if (result.stop_reason.empty())
    result.stop_reason = "completed";
  result.energy = solver->energy();
  result.fallbacks = solver->fallbacks();
  result.energy_balance_error =
      std::abs(result.energy.absolute_error()) / std::max(std::abs(result.energy.input), 1e-30);
  return result;
}

} // namespace brb::frame
