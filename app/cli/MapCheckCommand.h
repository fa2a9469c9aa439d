// `relief-cli info --check`: whether a material's normal and height maps agree with each other
// and with what the material declares (core/generators/MapCheck.h).
#pragma once

#include <QStringList>

namespace relief::cli {

// Arguments as runInfo received them, --check among them.
int runMapCheck(const QStringList& arguments);

}  // namespace relief::cli
