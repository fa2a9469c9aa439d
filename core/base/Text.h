// Small text helpers the readers share: ASCII lower case (names, extensions) and a path's
// extension. Paths are file-system bytes, so only ASCII letters change.
#pragma once

#include <string>
#include <string_view>

namespace relief::core::inline base {

std::string lowerCase(std::string_view text);
// "png" for "Maps/Bricks.PNG"; empty when the file name has no extension.
std::string lowerExtension(std::string_view path);

}  // namespace relief::core::base
