#pragma once
// Writes a whole file or nothing: the text goes to a temporary file beside the target, which
// is then renamed over it, so a failed write never leaves a half-written or emptied file.

#include <optional>
#include <string>

namespace linkwright::cli {

/// nullopt on success, else a sentence naming the file and the reason.
std::optional<std::string> writeFileAtomically(const std::string& path, const std::string& contents);

}  // namespace linkwright::cli
