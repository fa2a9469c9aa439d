// ParameterSlider; see ParameterSlider.h.
#include "ui/panels/ParameterSlider.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QSlider>

#include <algorithm>
#include <cmath>

namespace relief::ui::inline panels {

ParameterSlider::ParameterSlider(const core::OptionSpec& spec, QWidget* parent)
    : QWidget(parent),
      m_spec(spec),
      m_slider(new QSlider(Qt::Horizontal)),
      m_spinBox(new QDoubleSpinBox) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(m_slider, 1);
  layout->addWidget(m_spinBox);

  const bool integral = spec.kind == core::ParamKind::Int;
  m_slider->setRange(0, integral ? int(spec.maximum - spec.minimum) : kSliderSteps);
  m_spinBox->setRange(spec.minimum, spec.maximum);
  m_spinBox->setDecimals(spec.decimals);
  m_spinBox->setSingleStep(integral ? 1.0 : std::pow(10.0, -spec.decimals) * 5.0);
  m_spinBox->setKeyboardTracking(false);
  m_spinBox->setMinimumWidth(72);
  m_spinBox->setAlignment(Qt::AlignRight);

  connect(m_slider, &QSlider::sliderPressed, this, &ParameterSlider::dragStarted);
  connect(m_slider, &QSlider::valueChanged, this, [this](int position) {
    const double value = fromSlider(position);
    {
      const QSignalBlocker block(m_spinBox);
      m_spinBox->setValue(value);
    }
    Q_EMIT valueEdited(value, m_slider->isSliderDown());
  });
  connect(m_spinBox, &QDoubleSpinBox::valueChanged, this, [this](double value) {
    {
      const QSignalBlocker block(m_slider);
      m_slider->setValue(toSlider(value));
    }
    Q_EMIT valueEdited(value, false);
  });
  setValue(spec.defaultValue);
}

double ParameterSlider::value() const {
  return m_spinBox->value();
}

void ParameterSlider::setValue(double value) {
  const QSignalBlocker blockSlider(m_slider);
  const QSignalBlocker blockSpin(m_spinBox);
  m_spinBox->setValue(value);
  m_slider->setValue(toSlider(value));
}

int ParameterSlider::toSlider(double value) const {
  double t = (value - m_spec.minimum) / (m_spec.maximum - m_spec.minimum);
  if (isLogarithmic()) {
    t = std::log(std::max(value, m_spec.minimum) / m_spec.minimum) /
        std::log(m_spec.maximum / m_spec.minimum);
  }
  return int(std::lround(t * m_slider->maximum()));
}

bool ParameterSlider::isLogarithmic() const {
  // Ranges over two decades (strength 0.01..200, shininess 1..256) need the slider's travel
  // spread evenly over the ratio, or the useful values sit in its first pixels.
  return m_spec.kind == core::ParamKind::Float && m_spec.minimum > 0.0 &&
         m_spec.maximum / m_spec.minimum >= 100.0;
}

double ParameterSlider::fromSlider(int position) const {
  const double t = double(position) / double(m_slider->maximum());
  const double value = isLogarithmic()
                           ? m_spec.minimum * std::pow(m_spec.maximum / m_spec.minimum, t)
                           : m_spec.minimum + t * (m_spec.maximum - m_spec.minimum);
  // Round to what the spin box shows so the slider never produces hidden digits.
  const double scale = std::pow(10.0, m_spec.decimals);
  return std::round(value * scale) / scale;
}

}  // namespace relief::ui::inline panels
