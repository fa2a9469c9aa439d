// CompareDialog: the 2D compare view (CompareView) with its controls: mode (wipe, side by side,
// difference, thresholded), gain x1-x100, threshold, channel, zoom to fit or 1:1, and the
// metrics of the pair. Non-modal, so the 3D viewport stays usable beside it.
#pragma once

#include "core/compression/CompressionReport.h"
#include "ui/Forward.h"

#include <QDialog>

#include <memory>

class QComboBox;
class QLabel;
class QSlider;
class QSpinBox;

namespace relief::ui::inline compare {

class CompareDialog : public QDialog {
  Q_OBJECT

 public:
  explicit CompareDialog(QWidget* parent = nullptr);

  void setComparison(const QString& title, std::shared_ptr<const core::Image> original,
                     std::shared_ptr<const core::Image> compressed,
                     const core::CompressionReport& report);

  CompareView* view() const { return m_view; }
  QComboBox* modeBox() const { return m_mode; }
  QComboBox* channelBox() const { return m_channel; }
  QSlider* gainSlider() const;
  ParameterSlider* gainControl() const { return m_gain; }
  QSpinBox* thresholdBox() const { return m_threshold; }

 private:
  CompareView* m_view;
  QComboBox* m_mode;
  QComboBox* m_channel;
  ParameterSlider* m_gain;
  QSpinBox* m_threshold;
  QLabel* m_zoomLabel;
  QLabel* m_metrics;
  QLabel* m_hover;
};

}  // namespace relief::ui::inline compare
