// Temporary files that must not outlive an interrupted process. Saves write beside their target
// and rename over it (AtomicFile.h, saveImage), so an interrupted save never leaves a half-written
// target; without this, Ctrl+C or a farm's SIGTERM in the middle of one would leave the hidden
// temporary behind. While a TemporaryFile lives, its path is known to the signal handler that
// removeTemporaryFilesOnSignal installs, which deletes it before the process ends.
#pragma once

#include <string>

namespace relief::core::inline base {

class TemporaryFile {
 public:
  explicit TemporaryFile(const std::string& path);
  ~TemporaryFile();  // forgets the path (the owner has renamed or removed the file)
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

 private:
  int m_slot;  // -1 when every slot was taken (the file is then not cleaned up on a signal)
};

// On SIGINT, SIGTERM or SIGHUP: deletes the live temporary files, then ends the process as the
// signal would have. For command-line programs; call once at start.
void removeTemporaryFilesOnSignal();

}  // namespace relief::core::inline base
