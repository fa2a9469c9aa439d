// WorkControl: how long work (generating a map, tracing a frame) reports progress and learns
// that it should stop. Both parts are optional; a default WorkControl never cancels.
#pragma once

#include <atomic>
#include <functional>

namespace relief::core::inline base {

struct WorkControl {
  std::function<void(double fraction)> progress;  // 0..1, called from any thread
  const std::atomic<bool>* cancel = nullptr;

  bool cancelled() const { return cancel && cancel->load(std::memory_order_relaxed); }
  void report(double fraction) const {
    if (progress)
      progress(fraction);
  }
};

}  // namespace relief::core::inline base
