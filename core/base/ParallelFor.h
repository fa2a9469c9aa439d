// parallelFor: runs body(i) for i in [0, count) on a thread pool in chunks, reporting progress
// and stopping early when cancelled. The image generators and the error view use it for their
// rows. The body must not itself call parallelFor.
#pragma once

#include "core/base/WorkControl.h"

#include <functional>

namespace relief::core::inline base {

// Returns false when the work was cancelled (some rows may not have run).
bool parallelFor(int count, const std::function<void(int index)>& body,
                 const WorkControl& control = {});

}  // namespace relief::core::inline base
