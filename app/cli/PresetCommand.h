// relief-cli preset validate|info FILE: checks a .relief preset the way the editor loads it,
// or prints everything it holds.
#pragma once

#include <QStringList>

namespace relief::cli {

int runPreset(const QStringList& arguments);

}  // namespace relief::cli
