#pragma once
// linkwright-cli's exit codes; --help and the README list the same table.

namespace linkwright::cli {

enum class ExitCode : int {
  Success = 0,         ///< the command did what was asked
  IoError = 1,         ///< the output file could not be written, or memory ran out
  BadInput = 2,        ///< unknown option, malformed or invalid value (the message names it); --forces without masses
  NotAssemblable = 3,  ///< the linkage cannot be assembled over (part of) the requested range
};

inline int toInt(ExitCode code) { return static_cast<int>(code); }

}  // namespace linkwright::cli
