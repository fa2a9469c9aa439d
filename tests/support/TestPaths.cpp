// TestPaths; see TestPaths.h.
#include "TestPaths.h"

#include <unistd.h>
#include <filesystem>
#include <string>

namespace relief::test {

std::string sourcePath(const std::string& relative) {
  return std::string(RELIEF_SOURCE_DIR) + "/" + relative;
}

std::string binaryPath(const std::string& relative) {
  return std::string(RELIEF_BINARY_DIR) + "/" + relative;
}

std::string samplePreset(const std::string& name) {
  return sourcePath("samples/" + name + "/" + name + ".relief");
}

std::string scratchFolder() {
  static const std::string folder = [] {
    const std::filesystem::path path =
        std::filesystem::path(RELIEF_BINARY_DIR) / "test-scratch" / std::to_string(::getpid());
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
    return path.string();
  }();
  return folder;
}

std::string failureOutputFolder() {
  const std::filesystem::path path = std::filesystem::path(RELIEF_BINARY_DIR) / "test-failures";
  std::filesystem::create_directories(path);
  return path.string();
}

}  // namespace relief::test
