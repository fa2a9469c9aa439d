// ParameterSlider: a slider and a spin box for one numeric parameter, kept in step. Emits
// every value while dragging (for live feedback) and tells when a drag starts, so that the
// whole drag becomes one undo step.
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

  QSlider* slider() const { return m_slider; }
  QDoubleSpinBox* spinBox() const { return m_spinBox; }

  static constexpr int kSliderSteps = 1000;

 Q_SIGNALS:
  void dragStarted();
  // `dragging` is true while the slider is held down.
  void valueEdited(double value, bool dragging);

 private:
  bool isLogarithmic() const;
  int toSlider(double value) const;
  double fromSlider(int position) const;

  const core::OptionSpec& m_spec;
  QSlider* m_slider;
  QDoubleSpinBox* m_spinBox;
};

}  // namespace relief::ui::inline panels
