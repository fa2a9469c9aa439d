// relief-cli-render: the executable `relief-cli render`, `relief-cli compare --rendered` (render
// --compression-error under the compare command's name) and `relief-cli batch` with render jobs,
// run (RenderHelper.h), with the same arguments; it links the renderer, Qt GUI and OpenGL, which
// the other commands never need.
#include "BatchCommand.h"
#include "CliCommon.h"
#include "DisplayCheck.h"
#include "RenderCommand.h"

#include "core/base/TemporaryFiles.h"
#include "renderer/OpenGLProbe.h"

#include <QGuiApplication>
#include <QSurfaceFormat>

#include <cstring>

int main(int argc, char* argv[]) {
  using namespace relief::cli;
  takeQuietFlag(argc, argv);
  relief::core::removeTemporaryFilesOnSignal();
  if (argc < 2 || std::strcmp(argv[1], "batch") != 0)
    return runRender(argc, argv);
  if (const std::string problem = relief::app::displayProblem(); !problem.empty()) {
    printError(QStringLiteral("batch: its render jobs need a display: ") +
               QString::fromStdString(problem));
    return kExitFailure;
  }
  QSurfaceFormat::setDefaultFormat(relief::renderer::requiredSurfaceFormat());
  QGuiApplication application(argc, argv);
  const RenderSession session;
  return runBatch(QGuiApplication::arguments(), RenderSession::runJob);
}
