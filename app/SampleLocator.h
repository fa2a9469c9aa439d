// Finds the bundled sample materials: $RELIEF_SAMPLES, then samples/ next to the installed
// executable (share/relief/samples beside bin/, the path packaging/ installs them to), then
// the source tree the program was built from.
#pragma once

#include <QString>

namespace relief::app {

QString samplesDirectory();
// The preset the editor opens with no arguments (the bricks sample), or empty if not found.
QString defaultSamplePreset();

}  // namespace relief::app
