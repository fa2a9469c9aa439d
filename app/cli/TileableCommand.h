// `relief-cli generate tileable`: a photo and every map aligned with it made into a seamless
// tile with one cut (core/generators/Tileable.h), written under the same names to a folder.
#pragma once

#include <QStringList>

namespace relief::cli {

// Arguments as runGenerate received them ("generate" and "tileable" among them).
int runTileable(const QStringList& arguments);

}  // namespace relief::cli
