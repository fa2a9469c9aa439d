// `relief-cli render`: renders a preset (or individual maps) offscreen through the same
// renderer as the viewport and writes the image.
#pragma once

#include <QStringList>

#include <memory>

namespace relief::renderer {
class OffscreenRenderer;
}

namespace relief::cli {

// Takes argc/argv because rendering needs a QGuiApplication, created only after the command
// line is valid and a display is known to be reachable.
int runRender(int argc, char* argv[]);

// Render jobs of a batch (BatchCommand.h), one after another in one offscreen renderer and GL
// context, made on the first job. Lives inside the batch's QGuiApplication; while it does,
// runJob renders one job's command line.
class RenderSession {
 public:
  RenderSession();
  ~RenderSession();
  RenderSession(const RenderSession&) = delete;
  RenderSession& operator=(const RenderSession&) = delete;

  static int runJob(const QStringList& arguments);

 private:
  std::unique_ptr<renderer::OffscreenRenderer> m_offscreen;
};

}  // namespace relief::cli
