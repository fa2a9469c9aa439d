// Text conversions between core (std::string, UTF-8) and Qt widgets (QString), used by every
// ui folder.
#pragma once

#include <QString>

#include <string_view>

namespace relief::ui {

inline QString toQString(std::string_view text) {
  return QString::fromUtf8(text.data(), qsizetype(text.size()));
}

}  // namespace relief::ui
