// `relief-cli compress --preset P --budget 6MB|--target-flip X|--target-psnr DB --out-dir D`:
// chooses every map's format (renderer/CompressionChooser.h), writes the chosen KTX2 files and
// choice.json into D, and prints the table of candidates and what was chosen and why. Runs in
// relief-cli-render (it renders the material), as `render PRESET --choose-compression`.
#pragma once

#include "CliCommon.h"

#include "core/material/Material.h"
#include "renderer/CompressionChooser.h"

#include <QCommandLineParser>
#include <QString>

#include <optional>

namespace relief::renderer {
class OffscreenRenderer;
}

namespace relief::cli {

struct ChooseRequest {
  renderer::ChooserRequest chooser;
  QString outDir;
  QString baseName;  // the files' prefix: the preset's file name without its extension
  bool progressLines = false;
};

// The options render takes for it (compress's names; they mean nothing to a plain render).
CliOptions chooseCompressionOptions();

// `compress --preset P ...` as the render helper parses it: "--preset P" becomes the render
// command's preset argument and --choose-compression is added.
QStringList chooseCompressionArguments(QStringList arguments);

// Reads the goal and the other options; an exit code when they are wrong.
std::optional<int> parseChooseRequest(const QCommandLineParser& parser, const QString& presetPath,
                                      ChooseRequest& request);

int runChooseCompression(renderer::OffscreenRenderer& offscreen, const core::Material& material,
                         const renderer::FrameSettings& frame, const ChooseRequest& request,
                         bool json);

}  // namespace relief::cli
