// bench-interaction: is a drag in the editor fluid? Opens the real main window with the viewport
// at 1280x720 on the cobblestones sample (POM 8/32, soft shadows), replays a two-second drag of
// the height-scale slider and a two-second camera orbit with mouse events every 16 ms (a user's
// pointer rate), and prints the frames drawn during each drag and after its release: the frame
// time (draw + glFinish, as the status bar shows it), the interval between frames, and the
// resolution scale the viewport chose. Target (issue 12): median frame during a drag at most
// 66 ms, the last frame at full resolution.
//
// Run: xvfb-run -a -s '-screen 0 1600x1000x24' build/release/tools/bench-interaction [--frames]
//      (--frames also lists every frame: when it was drawn, its time and scale; --budget MS sets
//      the viewport's interactive frame budget instead of its default)
#include "renderer/OpenGLProbe.h"
#include "ui/panels/ParameterPanel.h"
#include "ui/panels/ParameterSlider.h"
#include "ui/viewport/ViewportWidget.h"
#include "ui/window/MainWindow.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QSlider>
#include <QSurfaceFormat>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#ifndef RELIEF_SOURCE_DIR
#error "RELIEF_SOURCE_DIR must point at the source tree (for the samples)"
#endif

namespace {

using namespace relief;

constexpr int kDragMs = 2000;
constexpr int kEventIntervalMs = 16;
constexpr int kAfterReleaseMs = 1200;
constexpr double kTargetMs = 66.0;
bool g_listFrames = false;

struct Frame {
  double atMs;  // since the drag started
  double milliseconds;
  double scale;
};

double median(std::vector<double> values) {
  if (values.empty())
    return 0.0;
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// Waits `milliseconds` while the event loop runs (frames are drawn).
void run(int milliseconds) {
  QElapsedTimer timer;
  timer.start();
  while (timer.elapsed() < milliseconds)
    QTest::qWait(std::min<int>(5, milliseconds - int(timer.elapsed()) + 1));
}

// Replays a drag on `target`: press at `start`, a move every kEventIntervalMs to `path(t)` for t
// from 0 to 1 over kDragMs, release; then waits for the view to rest. Prints one table row.
bool replay(const char* name, ui::ViewportWidget* viewport, QWidget* target, QPoint start,
            const std::function<QPoint(double)>& path) {
  std::vector<Frame> frames;
  QElapsedTimer clock;
  const QMetaObject::Connection connection = QObject::connect(
      viewport, &ui::ViewportWidget::frameRendered, [&](double milliseconds, double scale) {
        frames.push_back({double(clock.nsecsElapsed()) / 1e6, milliseconds, scale});
      });
  clock.start();
  QTest::mousePress(target, Qt::LeftButton, {}, start);
  QPoint last = start;
  while (clock.elapsed() < kDragMs) {
    last = path(double(clock.elapsed()) / kDragMs);
    QTest::mouseMove(target, last);
    QTest::qWait(kEventIntervalMs);
  }
  const double releasedAt = double(clock.nsecsElapsed()) / 1e6;
  QTest::mouseRelease(target, Qt::LeftButton, {}, last);
  run(kAfterReleaseMs);
  QObject::disconnect(connection);

  if (g_listFrames) {
    for (const Frame& frame : frames)
      std::printf("  %s frame at %7.1f ms: %6.1f ms, scale %.3f\n", name, frame.atMs,
                  frame.milliseconds, frame.scale);
    std::printf("  %s released at %.1f ms\n", name, releasedAt);
  }
  std::vector<double> during, intervals, scales;
  double previousAt = -1.0;
  for (const Frame& frame : frames) {
    if (frame.atMs > releasedAt)
      break;
    during.push_back(frame.milliseconds);
    scales.push_back(frame.scale);
    if (previousAt >= 0.0)
      intervals.push_back(frame.atMs - previousAt);
    previousAt = frame.atMs;
  }
  double fullAfterMs = -1.0, fullFrameMs = 0.0;
  for (const Frame& frame : frames) {
    if (frame.atMs > releasedAt && frame.scale >= 1.0) {
      fullAfterMs = frame.atMs - releasedAt;
      fullFrameMs = frame.milliseconds;
      break;
    }
  }
  const bool lastFull = !frames.empty() && frames.back().scale >= 1.0;
  const double medianMs = median(during);
  // A drag that stops changing anything before the release (a slider at its end) rests, and
  // its full frame comes before the release: nothing is left to draw after it.
  char afterRelease[64];
  if (fullAfterMs >= 0.0)
    std::snprintf(afterRelease, sizeof afterRelease, "%.0f ms (%.0f ms frame)", fullAfterMs,
                  fullFrameMs);
  else
    std::snprintf(afterRelease, sizeof afterRelease, "%s", lastFull ? "rested before it" : "none");
  std::printf(
      "| %s | %zu | %.1f ms | %.1f ms | %.1f ms | %.0f%% | %s | %s |\n", name, during.size(),
      medianMs, during.empty() ? 0.0 : *std::max_element(during.begin(), during.end()),
      median(intervals), median(scales) * 100.0, lastFull ? "full" : "REDUCED", afterRelease);
  return !during.empty() && medianMs <= kTargetMs && lastFull;
}

}  // namespace

int main(int argc, char* argv[]) {
  QSurfaceFormat::setDefaultFormat(renderer::requiredSurfaceFormat());
  QApplication application(argc, argv);
  g_listFrames = QCoreApplication::arguments().contains(QStringLiteral("--frames"));
  if (auto probe = renderer::probeOpenGL(); !probe) {
    std::fprintf(stderr, "bench-interaction: %s\n", probe.error().c_str());
    return 1;
  }
  ui::MainWindow window;
  window.show();
  if (!QTest::qWaitForWindowExposed(&window) ||
      !window.openPreset(
          QStringLiteral(RELIEF_SOURCE_DIR "/samples/cobblestones/cobblestones.relief"))) {
    std::fprintf(stderr, "bench-interaction: cannot open the window on the cobblestones sample\n");
    return 1;
  }
  ui::ViewportWidget* viewport = window.viewport();
  if (const qsizetype at = QCoreApplication::arguments().indexOf(QStringLiteral("--budget"));
      at >= 0 && at + 1 < QCoreApplication::arguments().size()) {
    viewport->setInteractiveFrameBudget(QCoreApplication::arguments().at(at + 1).toDouble());
  }
  // Grow the window until the viewport (between the docks) is 1280x720.
  for (int attempt = 0; attempt < 5 && viewport->size() != QSize(1280, 720); ++attempt) {
    window.resize(window.size() + QSize(1280, 720) - viewport->size());
    run(200);
  }
  run(1500);  // the first frames: shader compilation, uploads
  std::printf(
      "bench-interaction: viewport %dx%d, cobblestones (POM 8/32, soft shadows), a move "
      "every %d ms for %d ms\n\n",
      viewport->width(), viewport->height(), kEventIntervalMs, kDragMs);
  std::printf(
      "| drag | frames | median frame | max frame | median interval | median scale | "
      "last frame | full frame after release |\n|---|---|---|---|---|---|---|---|\n");

  auto* heightScale = qobject_cast<ui::ParameterSlider*>(
      window.parameterPanel()->editor(core::ParamId::HeightScale));
  QSlider* slider = heightScale->slider();
  const QPoint sliderStart(slider->width() / 8, slider->height() / 2);
  // The slider is pressed on its groove, which jumps the handle there, then swept to and fro.
  const bool sliderMet =
      replay("height-scale slider", viewport, slider, sliderStart, [&](double t) {
        const double sweep = 0.5 - 0.5 * std::cos(t * 2.0 * 3.14159265358979);
        return QPoint(int(slider->width() * (0.125 + 0.5 * sweep)), slider->height() / 2);
      });
  run(500);
  const QPoint centre = viewport->rect().center();
  const bool orbitMet = replay("camera orbit", viewport, viewport, centre, [&](double t) {
    const double angle = t * 2.0 * 3.14159265358979;
    return centre + QPoint(int(200.0 * std::sin(angle)), int(80.0 * (1.0 - std::cos(angle))));
  });
  const bool met = sliderMet && orbitMet;
  std::printf(
      "\nTarget: median frame during a drag at most %.0f ms, the last frame at full "
      "resolution: %s\n",
      kTargetMs, met ? "met" : "MISSED");
  return met ? 0 : 1;
}
