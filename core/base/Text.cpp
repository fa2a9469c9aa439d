// Text; see Text.h.
#include "core/base/Text.h"

#include <algorithm>
#include <cctype>

namespace relief::core::inline base {

std::string lowerCase(std::string_view text) {
  std::string result(text);
  std::transform(result.begin(), result.end(), result.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return result;
}

std::string lowerExtension(std::string_view path) {
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of("/\\");
  if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash))
    return {};
  return lowerCase(path.substr(dot + 1));
}

}  // namespace relief::core::base
