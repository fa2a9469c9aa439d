#include "core/base/InputFile.h"

#include <cerrno>
#include <cstring>

#include <sys/stat.h>

namespace relief::core::inline base {
namespace {

std::string whatItIs(mode_t mode) {
  if (S_ISDIR(mode))
    return "a folder";
  if (S_ISFIFO(mode))
    return "a FIFO (a pipe)";
  if (S_ISCHR(mode))
    return "a character device";
  if (S_ISBLK(mode))
    return "a block device";
  if (S_ISSOCK(mode))
    return "a socket";
  return "not a regular file";
}

// "16 MiB", "2 GiB", "512 bytes": sizes in messages.
std::string describeBytes(std::uintmax_t bytes) {
  constexpr std::uintmax_t kMiB = std::uintmax_t(1) << 20;
  constexpr std::uintmax_t kGiB = std::uintmax_t(1) << 30;
  if (bytes >= kGiB && bytes % kGiB == 0)
    return std::to_string(bytes / kGiB) + " GiB";
  if (bytes >= kMiB)
    return std::to_string(bytes / kMiB) + " MiB";
  return std::to_string(bytes) + " bytes";
}

}  // namespace

Result<std::uintmax_t> checkInputFile(const std::string& path, std::uintmax_t maxBytes,
                                      const std::string& kind) {
  // stat(), not std::filesystem: it tells a FIFO from a device in one call, follows links and
  // gives the errno when the path cannot be looked at (a missing folder, no permission).
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    const int error = errno;
    if (error == ENOENT)
      return makeError(path + ": file not found");
    return makeError(path + ": cannot be read (" + std::strerror(error) + ")");
  }
  if (!S_ISREG(info.st_mode))
    return makeError(path + ": " + whatItIs(info.st_mode) + ", not a regular file");
  const auto size = std::uintmax_t(info.st_size);
  if (size == 0)
    return makeError(path + ": the file is empty (0 bytes)");
  if (size > maxBytes) {
    return makeError(path + ": " + describeBytes(size) + " is larger than any " + kind +
                     " (the limit is " + describeBytes(maxBytes) + ")");
  }
  return size;
}

}  // namespace relief::core::inline base
