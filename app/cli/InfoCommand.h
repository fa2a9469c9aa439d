// `relief-cli info <image>`: size, channels, bit depth and colour space of an image file.
#pragma once

#include <QStringList>

namespace relief::cli {

int runInfo(const QStringList& arguments);

}  // namespace relief::cli
