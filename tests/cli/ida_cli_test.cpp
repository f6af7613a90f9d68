// `brb ida` end to end on the linear test frame (tests/support/linear_frame.hpp): rejected
// inputs write nothing, any thread count gives the same points, a study killed twice at
// random moments and resumed gives the outputs of an uninterrupted one, and (when built with
// MPI) three MPI ranks give the points of the threaded run.
#include "cli/run_brb.hpp"
#include "support/linear_frame.hpp"
#include "support/shared_records.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <chrono>
#include <iostream>
#include <random>
#include <thread>

extern char** environ;

namespace brb::testing {
namespace {

namespace fs = std::filesystem;

/// The suite of the tests: shared records, absolute paths.
std::string suite_json(std::initializer_list<std::string_view> names) {
  nlohmann::json records = nlohmann::json::array();
  for (const std::string_view name : names)
    records.push_back({{"file", (test::shared_ground_motions() / name).string()}});
  return nlohmann::json{{"records", records}}.dump();
}

/// A CSV without the columns whose header contains `skip` (e.g. run_time_s).
std::string without_column(const std::string& csv, const std::string& skip) {
  const std::vector<std::string> lines = lines_of(csv);
  if (lines.empty())
    return {};
  std::vector<bool> keep;
  {
    std::istringstream header(lines.front());
    for (std::string cell; std::getline(header, cell, ',');)
      keep.push_back(cell.find(skip) == std::string::npos);
  }
  std::string out;
  for (const std::string& line : lines) {
    std::istringstream row(line);
    std::size_t column = 0;
    for (std::string cell; std::getline(row, cell, ','); ++column)
      if (column >= keep.size() || keep[column])
        out += cell + ",";
    out += "\n";
  }
  return out;
}

/// summary.json without what describes the session (time, jobs, runs of this session).
nlohmann::json study_summary(const fs::path& file) {
  nlohmann::json summary = nlohmann::json::parse(read_file(file));
  for (const char* key : {"wall_time_s", "jobs", "runs_this_session", "parallelism"})
    summary.erase(key);
  return summary;
}

class IdaCli : public ::testing::Test {
protected:
  IdaCli() {
    model_ = scratch_.write("frame.json", test::kLinearFrame);
    suite_ = scratch_.write("suite.json", suite_json({"elCentro.AT2", "ARL360.at2", "RIO270.AT2"}));
  }
  std::string arguments(const fs::path& out, const std::string& extra = "", int runs = 10) const {
    return shell_quoted(model_.string()) + " --suite " + shell_quoted(suite_.string()) + " --out " +
           shell_quoted(out.string()) +
           " --first 0.25 --step 0.5 --step-growth 0.25 --resolution 0.02 --quiet --runs " +
           std::to_string(runs) + " " + extra;
  }
  CliRun ida(const fs::path& out, const std::string& extra = "", int runs = 10) const {
    return run_brb("ida " + arguments(out, extra, runs));
  }

  ScratchDirectory scratch_;
  fs::path model_, suite_;
};

TEST_F(IdaCli, WritesEveryOutputAndOneJournalLinePerRun) {
  const fs::path out = scratch_.path() / "out";
  const CliRun run = ida(out, "--jobs 2 --mce 1.5");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* file : {"ida_points.csv", "ida_curves.csv", "ida_fractiles.csv",
                           "collapse_fragility.csv", "summary.json", "journal.jsonl"})
    EXPECT_TRUE(fs::exists(out / file)) << file;
  const std::vector<std::string> points = lines_of(read_file(out / "ida_points.csv"));
  const std::vector<std::string> journal = lines_of(read_file(out / "journal.jsonl"));
  EXPECT_EQ(journal.size(), points.size()); // header line vs header row
  const nlohmann::json summary = nlohmann::json::parse(read_file(out / "summary.json"));
  EXPECT_EQ(summary["runs"].get<std::size_t>(), points.size() - 1);
  EXPECT_EQ(summary["records"].size(), 3u);
  // the linear frame collapses every record at drift_limit / slope: no censoring
  EXPECT_EQ(summary["fragility"]["collapses"], 3);
  const double median = summary["fragility"]["median_g"].get<double>();
  EXPECT_DOUBLE_EQ(summary["fragility"]["collapse_margin_ratio"].get<double>(), median / 1.5);
}

TEST_F(IdaCli, ThreadCountDoesNotChangeTheOutputs) {
  const fs::path one = scratch_.path() / "one", two = scratch_.path() / "two";
  ASSERT_EQ(ida(one, "--jobs 1").exit_code, 0);
  ASSERT_EQ(ida(two, "--jobs 2").exit_code, 0);
  EXPECT_EQ(without_column(read_file(one / "ida_points.csv"), "run_time"),
            without_column(read_file(two / "ida_points.csv"), "run_time"));
  for (const char* file : {"ida_curves.csv", "ida_fractiles.csv", "collapse_fragility.csv"})
    EXPECT_EQ(read_file(one / file), read_file(two / file)) << file;
  EXPECT_EQ(study_summary(one / "summary.json"), study_summary(two / "summary.json"));
}

/// Starts `brb ida ...` and kills it (SIGKILL) after `delay`; returns whether it was still
/// running when killed.
bool run_and_kill(const std::vector<std::string>& argv, std::chrono::milliseconds delay) {
  std::vector<char*> args;
  for (const std::string& arg : argv)
    args.push_back(const_cast<char*>(arg.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  EXPECT_EQ(spawned, 0);
  std::this_thread::sleep_for(delay);
  const bool running = ::kill(pid, SIGKILL) == 0;
  int status = 0;
  ::waitpid(pid, &status, 0);
  return running && WIFSIGNALED(status);
}

TEST_F(IdaCli, KilledTwiceAndResumedGivesTheUninterruptedOutputs) {
  // all ten shared records: a study of a few seconds, long enough to be killed mid-way
  suite_ = scratch_.write(
      "suite.json",
      suite_json({"ARL360.at2", "RIO270.AT2", "RSN6_IMPVALL.I_I-ELC180.AT2",
                  "RSN753_LOMAP_CLS000.AT2", "RSN77_SFERN_PUL164.AT2", "RSN879_LANDERS_LCN260.AT2",
                  "Rinaldi228.AT2", "TAK000.AT2", "TCU052-N.AT2", "elCentro.AT2"}));
  const fs::path whole = scratch_.path() / "whole", killed = scratch_.path() / "killed";
  const auto started = std::chrono::steady_clock::now();
  ASSERT_EQ(ida(whole, "--jobs 2").exit_code, 0);
  const auto duration = std::chrono::duration_cast<std::chrono::milliseconds>(
      std::chrono::steady_clock::now() - started);

  std::random_device entropy;
  const unsigned seed = entropy();
  std::mt19937 random(seed);
  SCOPED_TRACE("kill times drawn with seed " + std::to_string(seed));
  const std::vector<std::string> argv = {BRB_CLI_PATH,
                                         "ida",
                                         model_.string(),
                                         "--suite",
                                         suite_.string(),
                                         "--out",
                                         killed.string(),
                                         "--first",
                                         "0.25",
                                         "--step",
                                         "0.5",
                                         "--step-growth",
                                         "0.25",
                                         "--resolution",
                                         "0.02",
                                         "--runs",
                                         "10",
                                         "--quiet",
                                         "--jobs",
                                         "2"};
  std::vector<std::string> resume = argv;
  resume.push_back("--resume");
  int kills = 0;
  for (int attempt = 0; attempt < 2; ++attempt) {
    // a random moment within the uninterrupted run's duration (start-up included)
    std::uniform_int_distribution<long> moment(1, std::max<long>(2, duration.count()));
    const std::chrono::milliseconds delay(moment(random));
    kills += run_and_kill(attempt == 0 ? argv : resume, delay) ? 1 : 0;
    // whatever was killed, the journal holds whole lines only
    if (fs::exists(killed / "journal.jsonl")) {
      const std::string journal = read_file(killed / "journal.jsonl");
      EXPECT_TRUE(journal.empty() || journal.back() == '\n') << "a partial journal line";
      for (const std::string& line : lines_of(journal))
        EXPECT_TRUE(nlohmann::json::accept(line)) << line;
    }
  }
  std::cout << "[ killed " << kills << " of 2 times before the end, seed " << seed << " ]\n";
  const CliRun finished = ida(killed, "--jobs 2 --resume");
  ASSERT_EQ(finished.exit_code, 0) << finished.err;
  EXPECT_EQ(without_column(read_file(whole / "ida_points.csv"), "run_time"),
            without_column(read_file(killed / "ida_points.csv"), "run_time"));
  for (const char* file : {"ida_curves.csv", "ida_fractiles.csv", "collapse_fragility.csv"})
    EXPECT_EQ(read_file(whole / file), read_file(killed / file)) << file;
  EXPECT_EQ(study_summary(whole / "summary.json"), study_summary(killed / "summary.json"));
  // each run once in the journal
  EXPECT_EQ(lines_of(read_file(whole / "journal.jsonl")).size(),
            lines_of(read_file(killed / "journal.jsonl")).size());
}

TEST_F(IdaCli, RejectedInputsWriteNothing) {
  struct Case {
    std::string extra;
    std::string message;
  };
  const fs::path bad_suite = scratch_.write("bad.json", R"({"records": [{"file": "x.rec"}]})");
  const std::vector<Case> cases = {
      {"--im sd", "--im"},
      {"--resolution 0", "--resolution"},
      {"--step -1", "--step"},
      {"--drift-limit 2", "--drift-limit"},
      {"--braces rigid", "--braces"},
  };
  for (const Case& bad : cases) {
    const fs::path out = scratch_.path() / "rejected";
    const CliRun run = ida(out, bad.extra);
    EXPECT_EQ(run.exit_code, 2) << bad.extra;
    EXPECT_NE(run.err.find(bad.message), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out)) << bad.extra;
  }
  const fs::path out = scratch_.path() / "rejected";
  const CliRun run =
      run_brb("ida " + shell_quoted(model_.string()) + " --suite " +
              shell_quoted(bad_suite.string()) + " --out " + shell_quoted(out.string()));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("bad.json: /records/0/file: no such record file"), std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(IdaCli, AnExistingJournalNeedsResume) {
  const fs::path out = scratch_.path() / "out";
  ASSERT_EQ(ida(out, "", 2).exit_code, 0);
  const std::string journal = read_file(out / "journal.jsonl");
  const CliRun again = ida(out, "", 2);
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_NE(again.err.find("--resume"), std::string::npos) << again.err;
  // other settings cannot resume this journal
  const CliRun other = ida(out, "--resume", 3);
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("journal.jsonl: the journal was written for other inputs "
                           "(trace/max_runs differs)"),
            std::string::npos)
      << other.err;
  EXPECT_EQ(read_file(out / "journal.jsonl"), journal);
}

#ifdef BRB_MPIEXEC
TEST_F(IdaCli, ThreeMpiRanksGiveTheThreadedPoints) {
  const fs::path threads = scratch_.path() / "threads", ranks = scratch_.path() / "ranks";
  ASSERT_EQ(ida(threads, "--jobs 2").exit_code, 0);
  // root in containers and CI: OpenMPI refuses to run as root unless told; containers often
  // forbid the cross-memory attach of its shared-memory transport: plain copies instead
  const std::string command = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
                              "OMPI_MCA_btl_vader_single_copy_mechanism=none " +
                              shell_quoted(BRB_MPIEXEC) + " --oversubscribe -np 3 " +
                              shell_quoted(BRB_CLI_PATH) + " ida " + arguments(ranks) + " > " +
                              shell_quoted((scratch_.path() / "mpi.log").string()) + " 2>&1";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
      << read_file(scratch_.path() / "mpi.log");
  EXPECT_EQ(without_column(read_file(threads / "ida_points.csv"), "run_time"),
            without_column(read_file(ranks / "ida_points.csv"), "run_time"));
  const nlohmann::json summary = nlohmann::json::parse(read_file(ranks / "summary.json"));
  EXPECT_EQ(summary["parallelism"], "mpi");
  EXPECT_EQ(summary["jobs"], 2);
}
#endif

} // namespace
} // namespace brb::testing
