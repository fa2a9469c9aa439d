// ParallelFor; see ParallelFor.h.
#include "core/base/ParallelFor.h"

#include <QThread>
#include <QThreadPool>
#include <QtConcurrent/QtConcurrentMap>

#include <algorithm>
#include <atomic>
#include <vector>

namespace relief::core::inline base {
namespace {

// The rows run on a pool of their own. Callers are often tasks on Qt's global pool themselves
// (a generator's preview and its full-size run side by side); if the rows went to the same
// pool, two such callers waiting for their rows would hold every thread and never get them.
// Row tasks never wait for anything, so this pool always drains.
QThreadPool& rowPool() {
  static QThreadPool* pool = [] {
    auto* created = new QThreadPool;
    created->setMaxThreadCount(std::max(1, QThread::idealThreadCount()));
    return created;
  }();
  return *pool;
}

}  // namespace

bool parallelFor(int count, const std::function<void(int)>& body, const WorkControl& control) {
  if (count <= 0)
    return !control.cancelled();
  // Chunks of rows: small enough to balance the pool and to answer a cancel quickly, large
  // enough that the pool's overhead stays negligible.
  const int chunk = std::clamp(count / 64, 1, 64);
  std::vector<int> starts;
  for (int start = 0; start < count; start += chunk)
    starts.push_back(start);
  std::atomic<int> done{0};
  QtConcurrent::blockingMap(&rowPool(), starts, [&](int start) {
    if (control.cancelled())
      return;
    const int end = std::min(start + chunk, count);
    for (int i = start; i < end; ++i)
      body(i);
    const int finished = done.fetch_add(end - start) + (end - start);
    control.report(double(finished) / double(count));
  });
  return !control.cancelled();
}

}  // namespace relief::core::inline base
