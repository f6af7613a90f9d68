// `brb solid` end to end: the real binary (BRB_CLI_PATH) on a bare steel bar meshed with
// hexahedra (120 elements, about a second per run) and on input errors.
#include "cli/run_brb.hpp"
#include "io/scratch_directory.hpp"
#include "support/kinematic_bar.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <string>
#include <vector>

namespace {

using brb::testing::CliRun;
using brb::testing::lines_of;
using brb::testing::numbers_of;
using brb::testing::read_file;
using brb::testing::run_brb;
using brb::testing::ScratchDirectory;
using brb::testing::shell_quoted;
using nlohmann::json;

namespace fs = std::filesystem;

// A bare 12 x 10 mm plate, 300 mm long, S275 with linear kinematic hardening; loaded in tension
// only (a bare bar this slender would buckle in compression).
constexpr double kYoungsModulus = 210000.0;     // MPa
constexpr double kYieldStress = 275.0;          // MPa
constexpr double kKinematicHardening = 21000.0; // MPa
constexpr double kPlateWidth = 12.0;            // mm
constexpr double kPlateDepth = 10.0;            // mm
constexpr double kCoreLength = 300.0;           // mm
constexpr double kYieldDeformation = kYieldStress / kYoungsModulus * kCoreLength;

json bar_brace() {
  return {{"name", "bare bar"},
          {"units", "mm"},
          {"core",
           {{"section", {{"shape", "rectangle"}, {"width", kPlateWidth}, {"depth", kPlateDepth}}},
            {"steel",
             {{"E", kYoungsModulus},
              {"nu", 0.3},
              {"fy", kYieldStress},
              {"H_kin", kKinematicHardening},
              {"H_iso", 0.0}}},
            {"yielding_length", kCoreLength},
            {"elements", 4}}},
          {"ends", "fixed"},
          {"imperfection", {{"amplitude", 0.0}}},
          {"solid", {{"elements_across_core", 2}}}};
}

/// Tension to 2.5 dy and elastic unloading to 1 dy in steps of dy / 2 (a CSV history, mm).
/// Not further: the quasi-static ramp's dynamics add up over longer histories (the clamped
/// option's grips, which hold the Poisson strain at the ends, left residual stresses that
/// rounded the reverse yield: 2.7 % of Py below the uniaxial law at 0.5 dy after a 2.5 dy peak).
std::vector<double> tension_history() {
  std::vector<double> history;
  for (const double in_dy : {0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 2.0, 1.5, 1.0})
    history.push_back(in_dy * kYieldDeformation);
  return history;
}

/// The bar's force under uniform strain through the closed-form uniaxial law of linear
/// kinematic hardening (tests/support/kinematic_bar.hpp).
std::vector<double> uniaxial_bar_forces(const std::vector<double>& deformations) {
  return brb::testing::KinematicBar{kYoungsModulus, kYieldStress, kKinematicHardening, kCoreLength,
                                    kPlateWidth * kPlateDepth}
      .forces(deformations);
}

struct SolidFiles {
  ScratchDirectory scratch;
  fs::path brace = scratch.path() / "bar.json";
  fs::path protocol = scratch.path() / "tension.csv";
  fs::path out = scratch.path() / "out";

  explicit SolidFiles(const json& brace_json) {
    std::ofstream(brace) << brace_json.dump(2);
    std::ofstream history(protocol);
    history << std::setprecision(17) << "deformation\n";
    for (const double d : tension_history())
      history << d << "\n";
  }

  /// The history's own points: a largest step above its dy / 2 steps.
  std::string arguments(const std::string& options = "") const {
    return "solid " + shell_quoted(brace.string()) + " --protocol " +
           shell_quoted(protocol.string()) + " --out " + shell_quoted(out.string()) +
           " --max-step " + std::to_string(0.6 * kYieldDeformation) +
           (options.empty() ? "" : " " + options);
  }
};

TEST(SolidCli, BareBarFollowsTheUniaxialLawAndWritesTheCyclicFiles) {
  const SolidFiles files(bar_brace());
  const CliRun run = run_brb(files.arguments());
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("brb solid: brace bare bar"), std::string::npos) << run.out << run.err;

  // hysteresis.csv: the columns of brb cyclic, one row per protocol point
  const auto lines = lines_of(read_file(files.out / "hysteresis.csv"));
  ASSERT_EQ(lines.size(), tension_history().size() + 1);
  EXPECT_EQ(lines.front(), "step,cycle,deformation,force,max_lateral_displacement,substeps");
  std::vector<double> deformations, forces;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto row = numbers_of(lines[i]);
    ASSERT_EQ(row.size(), 6u);
    deformations.push_back(row[2]);
    forces.push_back(row[3]);
    EXPECT_NEAR(row[2], tension_history()[i - 1], 1e-9 * kYieldDeformation) << lines[i];
    if (i > 1) {
      EXPECT_GT(row[5], 0.0) << "explicit steps of the record: " << lines[i];
    }
  }
  // The 3D steel law collapses exactly to the uniaxial one in uniaxial stress, which the end
  // faces held on their centre lines (the default) leave uniform along the bar: within 0.5 %
  // of Py at every point (the quasi-static ramp's dynamics; the grips of the clamped option
  // restrain the Poisson strain at the ends and were 2.7 % off after the reversal).
  const std::vector<double> expected = uniaxial_bar_forces(deformations);
  const double yield_force = kYieldStress * kPlateWidth * kPlateDepth;
  double worst = 0.0;
  for (std::size_t k = 0; k < forces.size(); ++k) {
    EXPECT_NEAR(forces[k], expected[k], 0.005 * yield_force)
        << "point " << k << " at " << deformations[k] << " mm";
    worst = std::max(worst, std::abs(forces[k] - expected[k]) / yield_force);
  }
  RecordProperty("worst_force_error_over_Py", std::to_string(worst));

  const json summary = json::parse(read_file(files.out / "summary.json"));
  EXPECT_TRUE(summary["completed"].get<bool>());
  EXPECT_NEAR(summary["yield_force"].get<double>(), yield_force, 1e-6 * yield_force);
  const json& solid = summary["solid"];
  EXPECT_GT(solid["elements"].get<int>(), 0);
  EXPECT_GT(solid["explicit_steps"].get<long>(), 0);
  EXPECT_EQ(solid["hourglass"].get<std::string>(), "elastic"); // the default control
  EXPECT_FALSE(solid.contains("hourglass_min_scale"));         // only with "tangent"
  // quasi-static: kinetic energy < 5 % of internal energy (issue 6), balance closed
  EXPECT_LT(solid["max_kinetic_over_internal"].get<double>(), 0.05);
  EXPECT_LT(solid["max_energy_balance_error"].get<double>(), 1e-3);
  EXPECT_LT(solid["max_hourglass_over_internal"].get<double>(), 0.05);
  // the ratios are judged above 1 % of the elastic energy at yield, P_y d_y / 2
  EXPECT_NEAR(solid["quasi_static_floor_N_mm"].get<double>(),
              0.01 * 0.5 * yield_force * summary["yield_deformation"].get<double>(),
              1e-9 * yield_force);
  // the final balance over the gross work (a scale that is never zero once loaded)
  const json& balance = summary["energy_balance"];
  EXPECT_GT(balance["gross_work"].get<double>(), 0.0);
  EXPECT_LT(balance["relative_error"].get<double>(), 1e-3);

  const auto energy_lines = lines_of(read_file(files.out / "energies.csv"));
  EXPECT_EQ(energy_lines.front(),
            "step,time,explicit_steps,deformation,force,kinetic,internal,"
            "hourglass,contact_stored,friction,damping,external,energy_error");
  EXPECT_EQ(energy_lines.size(), lines.size());
}

TEST(SolidCli, WritesTheChosenSnapshotsAndTheirCollection) {
  const SolidFiles files(bar_brace());
  const CliRun run = run_brb(files.arguments("--snapshots 0,4 --outputs-per-step 1"));
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  const json summary = json::parse(read_file(files.out / "summary.json"));
  const int elements = summary["solid"]["elements"].get<int>();
  const int nodes = summary["solid"]["nodes"].get<int>();
  for (const char* name : {"step_000000.vtu", "step_000004.vtu"}) {
    const std::string text = read_file(files.out / "fields" / name);
    EXPECT_NE(text.find("NumberOfPoints=\"" + std::to_string(nodes) + "\""), std::string::npos);
    EXPECT_NE(text.find("NumberOfCells=\"" + std::to_string(elements) + "\""), std::string::npos);
    for (const char* field : {"displacement", "contact_pressure", "equivalent_plastic_strain",
                              "steel_damage", "mortar_damage"})
      EXPECT_NE(text.find(std::string("Name=\"") + field + "\""), std::string::npos) << field;
  }
  EXPECT_FALSE(fs::exists(files.out / "fields" / "step_000002.vtu"));
  const std::string pvd = read_file(files.out / "fields.pvd");
  EXPECT_NE(pvd.find("fields/step_000000.vtu"), std::string::npos) << pvd;
  EXPECT_NE(pvd.find("fields/step_000004.vtu"), std::string::npos) << pvd;
}

TEST(SolidCli, HistoriesWriteTheElementOutputsAfterEveryStep) {
  const SolidFiles files(bar_brace());
  const CliRun run = run_brb(files.arguments("--histories"));
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("element_history.csv"), std::string::npos) << run.out;
  const auto hysteresis = lines_of(read_file(files.out / "hysteresis.csv"));
  const auto history = lines_of(read_file(files.out / "element_history.csv"));
  // the columns of brb cyclic --histories, one row per step after the initial 0
  EXPECT_EQ(history.front(),
            "step,core_strain,dissipated_energy,cumulative_inelastic_deformation,"
            "max_core_lateral_displacement,max_casing_lateral_displacement,"
            "max_buckling_half_waves,max_steel_damage,max_mortar_damage,"
            "min_bearing_residual_strength,core_fracture,casing_failure,global_buckling");
  ASSERT_EQ(history.size(), hysteresis.size() - 1);
  for (std::size_t k = 1; k < history.size(); ++k) {
    const auto row = numbers_of(history[k]);
    const auto point = numbers_of(hysteresis[k + 1]);
    ASSERT_EQ(row.size(), 13u) << history[k];
    EXPECT_EQ(row[0], point[0]);
    // the bar has no end zones: its strain is the deformation over its length
    EXPECT_NEAR(row[1], point[2] / kCoreLength, 1e-12) << history[k];
    EXPECT_EQ(row[9], 1.0) << "no casing: no mortar has softened";
  }
  // the last row holds what summary.json reports for the whole run
  const json summary = json::parse(read_file(files.out / "summary.json"));
  const auto last = numbers_of(history.back());
  EXPECT_NEAR(last[3], summary["element"]["cumulative_inelastic_deformation"].get<double>(), 1e-9);
  EXPECT_GT(last[3], 0.0) << "the bar yielded";
}

TEST(SolidCli, ProgressPrintsOneLinePerRecordAtZeroSecondsAndEndsAtTheLast) {
  const SolidFiles files(bar_brace());
  const CliRun run = run_brb(files.arguments("--progress 0"));
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  const auto hysteresis = lines_of(read_file(files.out / "hysteresis.csv"));
  const std::size_t records = hysteresis.size() - 2; // past the header and the initial point
  std::size_t lines = 0;
  std::string last;
  for (const std::string& line : lines_of(run.err)) {
    if (line.rfind("brb: solid: step ", 0) == 0) {
      ++lines;
      last = line;
    }
  }
  // one per record (0 s), the initial one too, the last one naming it and 100 %
  EXPECT_EQ(lines, records + 1) << run.err;
  const std::string tail =
      std::to_string(records) + " of " + std::to_string(records) + " (100.0 %)";
  EXPECT_NE(last.find(tail), std::string::npos) << last;
  // a bad interval is a usage error naming the option
  const CliRun bad = run_brb(files.arguments("--progress=-1"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--progress"), std::string::npos) << bad.err;
}

TEST(SolidCli, TheShortestExcursionTimeIsKeptInTheSummaryAndExcludesADuration) {
  const SolidFiles files(bar_brace());
  const CliRun run = run_brb(files.arguments("--min-excursion-time 0.5"));
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  const json summary = json::parse(read_file(files.out / "summary.json"));
  EXPECT_EQ(summary["solid"]["min_excursion_time_s"].get<double>(), 0.5);
  // every excursion of the history lasts at least 0.5 s: the run at least that per excursion
  EXPECT_GE(summary["solid"]["duration_s"].get<double>(), 0.5);

  const SolidFiles both(bar_brace());
  const CliRun refused = run_brb(both.arguments("--min-excursion-time 0.5 --duration 2"));
  EXPECT_EQ(refused.exit_code, 2) << refused.out << refused.err;
  EXPECT_NE(refused.err.find("--min-excursion-time"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(both.out));
}

TEST(SolidCli, TheLateralDampingAndItsEnergyAreReported) {
  // The bare bar's only lateral motion is its Poisson contraction: the damping takes a small
  // positive energy, which summary.json reports beside alpha, as the energy balance's
  // released_in_jumps, and energies.csv per record; a negative alpha is a usage error.
  const SolidFiles files(bar_brace());
  const CliRun run = run_brb(files.arguments("--lateral-damping 20000"));
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("lateral damping 2e+04 1/s took"), std::string::npos) << run.out;
  const json summary = json::parse(read_file(files.out / "summary.json"));
  const json& solid = summary["solid"];
  EXPECT_EQ(solid["lateral_damping_per_s"].get<double>(), 20000.0);
  const double damping = solid["damping_energy_N_mm"].get<double>();
  EXPECT_GT(damping, 0.0);
  EXPECT_LT(solid["damping_energy_over_external_work"].get<double>(), 1e-2);
  EXPECT_EQ(summary["energy_balance"]["released_in_jumps"].get<double>(), damping);
  EXPECT_LT(summary["energy_balance"]["relative_error"].get<double>(), 1e-3);
  const auto energy_lines = lines_of(read_file(files.out / "energies.csv"));
  EXPECT_NEAR(numbers_of(energy_lines.back())[10], damping, 1e-9 * damping);

  const SolidFiles negative(bar_brace());
  const CliRun refused = run_brb(negative.arguments("--lateral-damping -1"));
  EXPECT_EQ(refused.exit_code, 2) << refused.out << refused.err;
  EXPECT_NE(refused.err.find("--lateral-damping"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(negative.out));
}

TEST(SolidCli, ABadSolidBlockIsAnInputErrorAndNothingIsWritten) {
  json brace = bar_brace();
  brace["solid"]["steel_density"] = -7.85e-9;
  const SolidFiles files(brace);
  const CliRun run = run_brb(files.arguments());
  EXPECT_EQ(run.exit_code, 2) << run.out << run.err;
  EXPECT_NE(run.err.find("/solid/steel_density"), std::string::npos) << run.out << run.err;
  EXPECT_FALSE(fs::exists(files.out));

  json coarse = bar_brace();
  coarse["solid"]["elements_across_core"] = 1; // too coarse to represent the core
  const SolidFiles coarse_files(coarse);
  const CliRun coarse_run = run_brb(coarse_files.arguments());
  EXPECT_EQ(coarse_run.exit_code, 2) << coarse_run.out << coarse_run.err;
  EXPECT_NE(coarse_run.err.find("/solid/elements_across_core"), std::string::npos)
      << coarse_run.out << coarse_run.err;
  EXPECT_FALSE(fs::exists(coarse_files.out));
}

} // namespace
