// InputError: a file the user gave us (JSON parameters, CSV histories) that the program
// cannot accept. The io layer throws it; the CLI prints it and exits with status 2.
#pragma once

#include <stdexcept>
#include <string>

namespace brb::io {

/// An unacceptable input file. The message always names the file, the place in it and what
/// was expected, in the form `<file>: <location>: <expected>`, e.g.
///   p.json: /fy: must be > 0 MPa (got -5)
///   history.csv: line 7, column strain: expected a finite number, got "abc"
/// The location is a JSON pointer ("/chaboche/1/C"), a CSV line and column, or empty when the
/// whole file is concerned (then the message is `<file>: <expected>`).
class InputError : public std::runtime_error {
public:
  InputError(std::string file, std::string location, std::string expected)
      : std::runtime_error(compose(file, location, expected)), file_(std::move(file)),
        location_(std::move(location)), expected_(std::move(expected)) {}

  const std::string& file() const { return file_; }
  const std::string& location() const { return location_; }
  const std::string& expected() const { return expected_; }

private:
  static std::string compose(const std::string& file, const std::string& location,
                             const std::string& expected) {
    return location.empty() ? file + ": " + expected : file + ": " + location + ": " + expected;
  }

  std::string file_;
  std::string location_;
  std::string expected_;
};

} // namespace brb::io
