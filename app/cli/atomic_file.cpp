#include "app/cli/atomic_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace linkwright::cli {

std::optional<std::string> writeFileAtomically(const std::string& path, const std::string& contents) {
  const std::filesystem::path target(path);
  std::filesystem::path temp = target;
  temp += ".linkwright-tmp";
  {
    std::ofstream file(temp, std::ios::binary | std::ios::trunc);
    if (!file) return "cannot write " + path + ": " + std::strerror(errno);
    errno = 0;
    file << contents;
    file.flush();
    if (!file) {
      const int why = errno;  // EFBIG or ENOSPC from the failed write, before remove() runs
      std::error_code ignored;
      std::filesystem::remove(temp, ignored);
      return "cannot write " + path + ": " + (why != 0 ? std::strerror(why) : "write failed");
    }
  }
  std::error_code ec;
  std::filesystem::rename(temp, target, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    return "cannot write " + path + ": " + ec.message();
  }
  return std::nullopt;
}

}  // namespace linkwright::cli
