// AtomicFile; see AtomicFile.h.
#include "core/base/AtomicFile.h"

#include "core/base/TemporaryFiles.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>

namespace relief::core::inline base {
namespace {

std::string temporaryPathFor(const std::filesystem::path& target) {
  static thread_local std::mt19937_64 random{std::random_device{}()};
  return (target.parent_path() /
          ("." + target.filename().string() + ".saving-" + std::to_string(random() % 1000000000)))
      .string();
}

Status failure(const std::string& path, const std::string& what, int error) {
  return makeError(path + ": cannot write (" + what + ": " + std::strerror(error) + ")");
}

}  // namespace

Status writeFileAtomically(const std::string& path, std::string_view bytes) {
  return writeFileAtomically(path, std::span<const std::string_view>(&bytes, 1));
}

Status writeFileAtomically(const std::string& path, std::span<const std::string_view> pieces) {
  const std::filesystem::path target = std::filesystem::absolute(path);
  const std::string temporary = temporaryPathFor(target);
  const TemporaryFile removedIfInterrupted(temporary);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0)
    return failure(path, "creating a temporary file", errno);

  // A file-size limit would otherwise kill the process with SIGXFSZ instead of failing the write.
  const auto previous = std::signal(SIGXFSZ, SIG_IGN);
  std::size_t total = 0;
  int error = 0;
  for (const std::string_view bytes : pieces) {
    std::size_t written = 0;
    while (!error && written < bytes.size()) {
      const ssize_t result = ::write(fd, bytes.data() + written, bytes.size() - written);
      if (result < 0) {
        if (errno != EINTR)
          error = errno;
        continue;
      }
      if (result == 0)
        error = EIO;
      written += std::size_t(result);
    }
    total += written;
  }
  std::signal(SIGXFSZ, previous);
  if (!error && ::fsync(fd) != 0)
    error = errno;
  struct stat status {};
  if (!error && (::fstat(fd, &status) != 0 || std::size_t(status.st_size) != total)) {
    error = error ? error : EIO;
  }
  if (::close(fd) != 0 && !error)
    error = errno;
  if (error) {
    ::unlink(temporary.c_str());
    return failure(path, "writing", error);
  }
  if (::rename(temporary.c_str(), target.c_str()) != 0) {
    error = errno;
    ::unlink(temporary.c_str());
    return failure(path, "replacing the file", error);
  }
  return {};
}

}  // namespace relief::core::inline base
