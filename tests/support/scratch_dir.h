#pragma once
// A fresh folder under the system's temporary directory for a test's files, named
// linkwright-<name>-<random> so that tests running at once never share one.

#include <filesystem>
#include <random>
#include <string>

namespace linkwright::test {

inline std::filesystem::path scratchDir(const std::string& name) {
  std::random_device random;
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("linkwright-" + name + "-" + std::to_string(random()));
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace linkwright::test
