// ParameterSlider: a slider and a spin box for one numeric parameter, kept in step. Emits
// every value while dragging (for live feedback) and tells when a drag starts, so that the
// whole drag becomes one undo step. The spin box takes typed values; Shift while dragging moves
// the value a tenth as fast (kFineDragFactor) for fine adjustment.
#pragma once

#include "core/material/Parameters.h"

#include <QWidget>

class QSlider;
class QDoubleSpinBox;

namespace relief::ui::inline panels {

class ParameterSlider : public QWidget {
  Q_OBJECT

 public:
  explicit ParameterSlider(const core::OptionSpec& spec, QWidget* parent = nullptr);

  double value() const;
  // Shows a value without emitting valueEdited.
  void setValue(double value);

  // Narrows or widens the range the controls offer (the spec's by default); the value is
  // clamped into it.
  void setRange(double minimum, double maximum);

  QSlider* slider() const { return m_slider; }
  QDoubleSpinBox* spinBox() const { return m_spinBox; }

  static constexpr int kSliderSteps = 1000;
  static constexpr double kFineDragFactor = 10.0;

 Q_SIGNALS:
  void dragStarted();
  // `dragging` is true while the slider is held down.
  void valueEdited(double value, bool dragging);

 private:
  bool eventFilter(QObject* watched, QEvent* event) override;
  bool isLogarithmic() const;
  int toSlider(double value) const;
  double fromSlider(int position) const;

  const core::OptionSpec& m_spec;
  double m_minimum;
  double m_maximum;
  // A Shift-drag: where it began (mouse x, slider position); fine while Shift is held.
  bool m_fineDrag = false;
  double m_fineAnchorX = 0.0;
  int m_fineAnchorPosition = 0;
  QSlider* m_slider;
  QDoubleSpinBox* m_spinBox;
};

}  // namespace relief::ui::inline panels
