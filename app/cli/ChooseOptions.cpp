// ChooseOptions; see ChooseOptions.h.
#include "ChooseOptions.h"

#include "app/cli/CliOptionNames.h"

namespace relief::cli {

CliOptions chooseGoalOptions() {
  return {
      {option::kBudget,
       QStringLiteral("size"),
       QStringLiteral("With --preset: the bytes all maps may take as shipped (KTX2 after "
                      "Zstandard): 6MB, 512KiB, 700000."),
       {}},
      {option::kTargetFlip,
       QStringLiteral("X"),
       QStringLiteral("With --preset: the fewest bytes whose rendered FLIP (mean over close, "
                      "grazing and far views) is at most X."),
       {}},
      {option::kTargetPsnr,
       QStringLiteral("dB"),
       QStringLiteral("With --preset: the fewest bytes whose rendered PSNR is at least this."),
       {}},
      {option::kDevice, QStringLiteral("desktop|mobile"),
       QStringLiteral("With --preset: BC formats, or ETC2/EAC and ASTC."),
       QStringLiteral("desktop")},
      {option::kOutDir,
       QStringLiteral("folder"),
       QStringLiteral("With --preset: where the chosen KTX2 files and choice.json go."),
       {}},
      {option::kProgressLines,
       {},
       QStringLiteral("With --preset (or compare --rendered --slot): progress as "
                      "'progress 0.42' lines on standard error (for a GUI or a build log)."),
       {}},
  };
}

}  // namespace relief::cli
