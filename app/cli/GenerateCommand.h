// `relief-cli generate <generator>`: the map generators in batch (normal, height,
// height-from-color, ao, curvature, pack), with the same option names and defaults as the GUI.
#pragma once

#include <QStringList>

namespace relief::cli {

int runGenerate(const QStringList& arguments);

}  // namespace relief::cli
