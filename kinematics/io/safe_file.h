#pragma once
// The one way Linkwright writes a file, for every output of the CLI and the designer (tables,
// documents, reports, drawings, images, animations). A file is written whole or not at all:
// - a regular file, or a new one, is replaced atomically: the bytes go to a temporary file of
//   a unique name beside it (two runs writing the same path never share one), every write and
//   the close are checked, the data is synced to disk, and only then is it renamed over the
//   target, which keeps its permissions; a failure removes the temporary file and leaves the
//   old file as it was;
// - a symbolic link's target is written that way, and the link kept;
// - a target that is not a regular file (a device such as /dev/null or /dev/stdout, a FIFO, a
//   terminal) is written through, never replaced;
// - a folder is refused.
// Errors name the path and the reason (field "output"). A process that installs
// removeTemporaryFilesOnSignals() also loses no temporary file to Ctrl+C, SIGTERM or SIGHUP.

#include "kinematics/model/result.h"

#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>

namespace linkwright::kinematics::io {

/// Writes the file at the path it is given (the temporary file, or the target itself when
/// that is not a regular file); why it failed ("No space left on device") if any write or
/// the close failed, else nullopt.
using FileWriter = std::function<std::optional<std::string>(const std::string& path)>;

/// Writes `path` through `write`, as above.
std::optional<Error> writeFileSafely(const std::string& path, const FileWriter& write);

/// What a streaming writer does with the stream it is given: writes its bytes, as many as it
/// has, and says why it stopped early (a core error) or nothing.
using StreamWriter = std::function<std::optional<std::string>(std::ostream& out)>;

/// Writes `path` as above from `write`, through a buffered stream whose every write, flush and
/// close is checked (a full disk fails with "No space left on device"): output that is
/// produced piece by piece (a table of 10⁷ rows) is never held whole in memory.
std::optional<Error> writeStreamSafely(const std::string& path, const StreamWriter& write);

/// Writes `contents` to `path`, as above.
std::optional<Error> writeFileSafely(const std::string& path, std::string_view contents);

/// Makes SIGINT, SIGTERM and SIGHUP remove the temporary files being written (the old files
/// stay as they were) and then end the process of that signal, as its default disposition
/// would, so the exit status is the signal's. A signal that is ignored or handled already is
/// left as it is (nohup's SIGHUP stays ignored). For a program's main (the CLI's): the handler
/// is process-wide. The pending names are a fixed table of C strings, so the handler only reads
/// them and calls unlink(), both async-signal-safe.
void removeTemporaryFilesOnSignals();

/// The Error for `path`: "cannot write PATH: WHY".
Error outputError(const std::string& path, const std::string& why);

}  // namespace linkwright::kinematics::io
