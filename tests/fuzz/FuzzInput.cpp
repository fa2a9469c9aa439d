#include "FuzzInput.h"

#include <unistd.h>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace relief::fuzz {
namespace {

namespace fs = std::filesystem;

fs::path& folderPath() {
  static fs::path folder;
  return folder;
}

const fs::path& fuzzFolder() {
  fs::path& folder = folderPath();
  if (folder.empty()) {
    const fs::path base =
        fs::is_directory("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
    folder = base / ("relief-fuzz-" + std::to_string(::getpid()));
    fs::create_directories(folder);
    // Removed when the process ends normally; a crash leaves the input for inspection.
    std::atexit([] {
      std::error_code ignored;
      fs::remove_all(folderPath(), ignored);
    });
  }
  return folder;
}

}  // namespace

std::string writeFuzzInput(const std::uint8_t* data, std::size_t size, std::string_view extension) {
  const fs::path path = fuzzFolder() / ("input." + std::string(extension));
  std::FILE* file = std::fopen(path.c_str(), "wb");
  const bool written = file && (size == 0 || std::fwrite(data, 1, size, file) == size);
  if (!file || std::fclose(file) != 0 || !written) {
    throw std::runtime_error("cannot write the fuzz input " + path.string());
  }
  return path.string();
}

}  // namespace relief::fuzz
