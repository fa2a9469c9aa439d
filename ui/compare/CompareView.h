// CompareView: a 2D comparison of a map with its compressed version. Zoom (wheel, about the
// cursor) and pan (drag) down to single texels, drawn without smoothing above 1:1 so every texel
// is exact; modes: a wipe with a draggable divider (original left), side by side, the
// difference amplified x1-x100, the thresholded difference of reference 003's figures, the
// FLIP error as a heat map (measured in the background: a large map takes seconds), and each
// block's RMS error as a heat map (the format's blocks, to see which ones went wrong); any
// mode can isolate one channel. Hovering shows the texel's values on both sides.
#pragma once

#include "core/image/Image.h"
#include "ui/Forward.h"

#include <QImage>
#include <QPointF>
#include <QString>
#include <QWidget>

#include <memory>
#include <optional>

namespace relief::ui::inline compare {

class CompareView : public QWidget {
  Q_OBJECT

 public:
  // Flip: the per-pixel FLIP error (core/compression/Flip.h) as a heat map. Blocks: each
  // block's RMS error (core::blockError) as a heat map over the map: which blocks went wrong.
  enum class Mode { Wipe, SideBySide, Difference, Threshold, Flip, Blocks };

  explicit CompareView(QWidget* parent = nullptr);

  void setImages(std::shared_ptr<const core::Image> original,
                 std::shared_ptr<const core::Image> compressed);
  void setMode(Mode mode);
  Mode mode() const { return m_mode; }
  void setGain(double gain);  // 1..100
  double gain() const { return m_gain; }
  void setThreshold(double threshold);  // 0..1 units of the map
  double threshold() const { return m_threshold; }
  void setChannel(std::optional<int> channel);  // empty: all
  std::optional<int> channel() const { return m_channel; }
  // The compressed format's block size, for the Blocks mode (4x4 unless told).
  void setBlockSize(int width, int height);
  void setWipeFraction(double fraction);
  double wipeFraction() const { return m_wipe; }

  double zoom() const { return m_zoom; }
  void setZoom(double zoom, QPointF anchor);  // keeps the image point under `anchor` in place
  void fitToView();
  void showActualPixels();  // 1:1
  // The widget position of an image texel's top-left corner (for tests and the readout).
  QPointF toWidget(QPointF texel) const;
  QPointF toTexel(QPointF widget) const;

  // What is drawn now, as an image the widget's size (for tests and saving).
  QImage picture();
  // Blocks until the FLIP error in flight (if any) is shown (tests).
  void waitForFlip();

  QSize sizeHint() const override { return {640, 480}; }

 Q_SIGNALS:
  void zoomChanged(double zoom);
  void hoverText(const QString& text);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void leaveEvent(QEvent* event) override;

 private:
  void rebuild();  // the display images for the mode, gain, threshold and channel
  int dividerX() const;
  // The read-out for the texel under the pointer, sent again whenever what is under it changes
  // (a move, a zoom, a pan, new images); empty when the pointer is off the images.
  void updateHover();

  std::shared_ptr<const core::Image> m_original, m_compressed;
  QImage m_left, m_right, m_difference;
  // The FLIP error, measured in the background on first use per pair of images, and its heat
  // map at the current gain.
  BackgroundTask* m_flipTask;
  std::optional<core::Image> m_flipError;
  QImage m_flipMap;
  double m_flipMean = 0.0;
  int m_blockWidth = 4, m_blockHeight = 4;
  double m_worstBlock = 0.0;  // the Blocks mode's largest RMS error, for its caption
  Mode m_mode = Mode::Wipe;
  double m_gain = 10.0;
  double m_threshold = 8.0 / 255.0;
  std::optional<int> m_channel;
  double m_wipe = 0.5;
  double m_zoom = 1.0;
  QPointF m_offset;          // widget position of texel (0, 0)
  bool m_userMoved = false;  // zoomed or panned since the last fit
  enum class Drag { None, Pan, Divider } m_drag = Drag::None;
  QPointF m_last;
  std::optional<QPointF> m_pointer;  // over the widget, where
};

}  // namespace relief::ui::inline compare
