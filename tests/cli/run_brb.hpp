// Running the real `brb` binary (BRB_CLI_PATH) from the CLI tests, and reading what it wrote.
#pragma once

#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <charconv>
#include <chrono>
#include <cstdlib>
#include <sstream>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace brb::testing {

/// `text` quoted for the POSIX shell.
inline std::string shell_quoted(const std::string& text) {
  std::string quoted = "'";
  for (const char character : text) {
    if (character == '\'') {
      quoted += "'\\''";
    } else {
      quoted += character;
    }
  }
  return quoted + "'";
}

struct CliRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

/// Runs `brb <arguments>` (already shell-quoted where needed); stdout and stderr are captured in
/// a directory of their own so that the working directory's listing shows only what brb wrote.
inline CliRun run_brb(const std::string& arguments) {
  const ScratchDirectory logs;
  const auto out = logs.path() / "stdout";
  const auto err = logs.path() / "stderr";
  const std::string command = shell_quoted(BRB_CLI_PATH) + " " + arguments + " >" +
                              shell_quoted(out.string()) + " 2>" + shell_quoted(err.string()) +
                              " </dev/null";
  const int status = std::system(command.c_str());
  CliRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = read_file(out);
  run.err = read_file(err);
  return run;
}

/// Starts `brb <arguments>` in the background and kills it (SIGKILL) as soon as `checkpoint`
/// exists (the run writes it after a converged step), then waits until the process is gone:
/// a run killed mid-way, for the checkpoint tests. False when no checkpoint appeared within a
/// minute.
inline bool run_brb_until_checkpoint(const std::string& arguments,
                                     const std::filesystem::path& checkpoint) {
  const ScratchDirectory scratch;
  const auto pid_file = scratch.path() / "pid";
  const std::string background = shell_quoted(BRB_CLI_PATH) + " " + arguments +
                                 " >/dev/null 2>&1 </dev/null & echo $! > " +
                                 shell_quoted(pid_file.string());
  if (std::system(background.c_str()) != 0)
    return false;
  for (int poll = 0; poll < 6000 && !std::filesystem::exists(checkpoint); ++poll)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::string pid = read_file(pid_file);
  pid.erase(pid.find_last_not_of(" \n") + 1);
  const std::string kill =
      "kill -9 " + pid + " 2>/dev/null; while kill -0 " + pid + " 2>/dev/null; do sleep 0.01; done";
  return std::system(kill.c_str()) == 0 && std::filesystem::exists(checkpoint);
}

inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);)
    lines.push_back(line);
  return lines;
}

/// The numbers of a CSV line; a cell that is not exactly a number fails the test.
inline std::vector<double> numbers_of(const std::string& line) {
  std::vector<double> numbers;
  std::istringstream stream(line);
  for (std::string cell; std::getline(stream, cell, ',');) {
    double value = 0.0;
    const auto [end, status] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
    EXPECT_TRUE(status == std::errc{} && end == cell.data() + cell.size()) << cell;
    numbers.push_back(value);
  }
  return numbers;
}

} // namespace brb::testing
