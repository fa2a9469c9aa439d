// The first rule every reader of untrusted files applies (images, DDS/KTX2 textures, presets,
// meshes): the path names a regular file (not a folder, FIFO, device or socket; links are
// followed, so a link to /dev/zero is refused too) that is neither empty nor larger than the
// reader's cap. Checked before a byte is read, so nothing blocks on a FIFO or reads forever.
// The caps of each kind of file are listed in docs/limits.md.
#pragma once

#include "core/base/Result.h"

#include <cstdint>
#include <string>

namespace relief::core::inline base {

// Returns the file's size in bytes, or a message that names the file and what it is instead.
// `kind` names the kind of file in the size message ("preset": "larger than any preset").
Result<std::uintmax_t> checkInputFile(const std::string& path, std::uintmax_t maxBytes,
                                      const std::string& kind);

}  // namespace relief::core::inline base
