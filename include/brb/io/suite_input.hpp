// Ground-motion suite files (DESIGN.md section 7, `suite`): the records an IDA runs, each
// with what its file does not say (units, time step) and an optional normalisation factor.
// Documented in the README ("Ground-motion suite files"). Paths are relative to the suite
// file. Every record is read when the suite is loaded, so that a missing file, unknown units,
// a single-column record without dt or two records of the same name are input errors before
// any run starts.
#pragma once

#include "brb/io/ground_motion.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace brb::io {

/// The ground direction a record acts along (the frame's global axes; z is vertical).
enum class SuiteDirection { x, y, z };

struct SuiteRecord {
  std::string name;           ///< unique in the suite; default: the file name without extension
  std::filesystem::path file; ///< resolved against the suite file's folder
  std::string component;      ///< a label (e.g. "ELC180"); informative only
  SuiteDirection direction = SuiteDirection::x;
  GroundMotionOptions options; ///< format, units, dt; `scale` holds the normalisation factor
};

struct GroundMotionSuite {
  std::filesystem::path source; ///< the suite file
  std::string name;             ///< default: the suite file name without extension
  std::string description;
  std::vector<SuiteRecord> records;
  std::vector<GroundMotion> motions; ///< records[i] read (units and factor applied)
};

/// Reads and checks a suite file and every record it names. InputError (file, JSON path,
/// expectation) for: a missing or malformed suite, no records, an unknown key, a missing
/// record file, unknown units or format, dt missing for a single-column file (or not > 0), a
/// factor that is not > 0, an unknown direction, a duplicate name; errors inside a record
/// file are InputErrors naming that file.
GroundMotionSuite read_suite(const std::filesystem::path& file);

} // namespace brb::io
