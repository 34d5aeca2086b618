#pragma once
// The one way Linkwright reads a whole input file (documents, other tools' tables, measured
// law tables), from the CLI and the designer: a regular file only (a device such as /dev/zero,
// a FIFO or a folder is refused before reading: it could be endless), and its size limit
// enforced while reading, so a file that grows past it is stopped there, not read to the end.

#include "kinematics/model/result.h"

#include <cstddef>
#include <string>

namespace linkwright::kinematics::io {

/// Documents: 16 MiB (a six-bar with masses and a law table of 10⁴ rows is under 1 MiB).
inline constexpr std::size_t kMaxDocumentBytes = 16u << 20;

/// The bytes of the file at `path`, or an Error (field "file") naming the path and why: it
/// cannot be opened (the system's reason), is not a regular file, or is larger than `limit`
/// bytes (said in MiB). `what` names the file's kind in the message ("a table", "a document").
Result<std::string> readFileBounded(const std::string& path, std::size_t limit, const std::string& what);

}  // namespace linkwright::kinematics::io
