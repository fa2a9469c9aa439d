// Writing a file so that it is either replaced whole or not at all: the bytes go to a temporary
// file beside the target, every write is checked, the data is flushed to disk, and only then is
// the temporary renamed over the target. Written here rather than with QSaveFile because Qt
// 6.4's QSaveFile::commit() reports success after a short write (seen with a file-size limit:
// the target was replaced by a truncated file), which is exactly the loss this must prevent.
#pragma once

#include "core/base/Result.h"

#include <span>
#include <string>
#include <string_view>

namespace relief::core::inline base {

// Fails with a message naming `path` and the reason; the previous file is then untouched.
Status writeFileAtomically(const std::string& path, std::string_view bytes);
// The file made of `pieces` one after another, written without joining them first (a
// container's header and its payload, which can be large, stay where they are).
Status writeFileAtomically(const std::string& path, std::span<const std::string_view> pieces);

}  // namespace relief::core::inline base
