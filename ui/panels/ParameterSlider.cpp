// ParameterSlider; see ParameterSlider.h.
#include "ui/panels/ParameterSlider.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QMouseEvent>
#include <QSignalBlocker>
#include <QSlider>

#include <algorithm>
#include <cmath>

namespace relief::ui::inline panels {

ParameterSlider::ParameterSlider(const core::OptionSpec& spec, QWidget* parent)
    : QWidget(parent),
      m_spec(spec),
      m_minimum(spec.minimum),
      m_maximum(spec.maximum),
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

  // What the value is, its unit, range and default: the spec says it once for every slider.
  setToolTip(QString::fromStdString(core::describeOption(spec)));
  m_slider->installEventFilter(this);
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

void ParameterSlider::setRange(double minimum, double maximum) {
  const double value = std::clamp(this->value(), minimum, maximum);
  m_minimum = minimum;
  m_maximum = maximum;
  if (m_spec.kind == core::ParamKind::Int) {
    const QSignalBlocker block(m_slider);
    m_slider->setRange(0, int(maximum - minimum));
  }
  {
    const QSignalBlocker block(m_spinBox);
    m_spinBox->setRange(minimum, maximum);
  }
  setValue(value);
}

bool ParameterSlider::eventFilter(QObject* watched, QEvent* event) {
  if (watched == m_slider && event->type() == QEvent::MouseButtonPress)
    m_fineDrag = false;
  if (watched != m_slider || event->type() != QEvent::MouseMove || !m_slider->isSliderDown())
    return QWidget::eventFilter(watched, event);
  const auto* mouse = static_cast<QMouseEvent*>(event);
  if (!(mouse->modifiers() & Qt::ShiftModifier)) {
    m_fineDrag = false;  // the slider follows the mouse again
    return false;
  }
  const double x = mouse->position().x();
  if (!m_fineDrag) {
    m_fineDrag = true;
    m_fineAnchorX = x;
    m_fineAnchorPosition = m_slider->sliderPosition();
  }
  const double positionsPerPixel =
      double(m_slider->maximum() - m_slider->minimum()) / double(std::max(m_slider->width(), 1));
  m_slider->setSliderPosition(
      m_fineAnchorPosition +
      int(std::lround((x - m_fineAnchorX) * positionsPerPixel / kFineDragFactor)));
  return true;  // the slider does not jump to the mouse
}

int ParameterSlider::toSlider(double value) const {
  double t = (value - m_minimum) / (m_maximum - m_minimum);
  if (isLogarithmic()) {
    t = std::log(std::max(value, m_minimum) / m_minimum) / std::log(m_maximum / m_minimum);
  }
  return int(std::lround(t * m_slider->maximum()));
}

bool ParameterSlider::isLogarithmic() const {
  // Ranges over two decades (strength 0.01..200, shininess 1..256) need the slider's travel
  // spread evenly over the ratio, or the useful values sit in its first pixels.
  return m_spec.kind == core::ParamKind::Float && m_minimum > 0.0 && m_maximum / m_minimum >= 100.0;
}

double ParameterSlider::fromSlider(int position) const {
  const double t = double(position) / double(m_slider->maximum());
  const double value = isLogarithmic() ? m_minimum * std::pow(m_maximum / m_minimum, t)
                                       : m_minimum + t * (m_maximum - m_minimum);
  // Round to what the spin box shows so the slider never produces hidden digits.
  const double scale = std::pow(10.0, m_spec.decimals);
  return std::round(value * scale) / scale;
}

}  // namespace relief::ui::inline panels
