// TemporaryFiles; see TemporaryFiles.h. The handler may only call async-signal-safe functions
// (unlink, signal, raise), so the paths sit in fixed slots, claimed with atomics, never in
// allocated memory.
#include "core/base/TemporaryFiles.h"

#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>

namespace relief::core::inline base {
namespace {

constexpr int kSlots = 64;  // files being written at once (one per save in progress)
constexpr int kLongestPath = 4096;

enum SlotState : int { Free, Claimed, Live };

struct Slot {
  std::atomic<int> state{Free};
  char path[kLongestPath] = {};
};

std::array<Slot, kSlots> g_slots;

void removeAndReraise(int signal) {
  for (Slot& slot : g_slots) {
    if (slot.state.load() == Live)
      ::unlink(slot.path);
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

}  // namespace

TemporaryFile::TemporaryFile(const std::string& path) : m_slot(-1) {
  if (path.size() >= std::size_t(kLongestPath))
    return;
  for (int i = 0; i < kSlots; ++i) {
    int expected = Free;
    if (g_slots[std::size_t(i)].state.compare_exchange_strong(expected, Claimed)) {
      std::memcpy(g_slots[std::size_t(i)].path, path.c_str(), path.size() + 1);
      g_slots[std::size_t(i)].state.store(Live);
      m_slot = i;
      return;
    }
  }
}

TemporaryFile::~TemporaryFile() {
  if (m_slot >= 0)
    g_slots[std::size_t(m_slot)].state.store(Free);
}

void removeTemporaryFilesOnSignal() {
  for (int signal : {SIGINT, SIGTERM, SIGHUP})
    std::signal(signal, removeAndReraise);
}

}  // namespace relief::core::inline base
