// The options of "choose for me" (`compress --preset P --budget ...`) that both parsers declare:
// compress's, for its --help and to refuse them without --preset, and the render helper's, which
// runs the choice (ChooseCompression.h). One table, so the two never describe them differently.
#pragma once

#include "CliCommon.h"

namespace relief::cli {

// --budget, --target-flip, --target-psnr, --device, --out-dir, --progress-lines.
CliOptions chooseGoalOptions();

}  // namespace relief::cli
