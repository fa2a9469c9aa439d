// relief-cli export --preset FILE --to package|gltf|godot --out DIR: takes a preset into a
// folder another project or engine reads (core/export).
#pragma once

#include <QStringList>

namespace relief::cli {

int runExport(const QStringList& arguments);

}  // namespace relief::cli
