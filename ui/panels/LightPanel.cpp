// LightPanel; see LightPanel.h.
#include "ui/panels/LightPanel.h"

#include "core/image/ColorSpace.h"
#include "ui/QtText.h"
#include "ui/document/ViewDocument.h"
#include "ui/panels/EnvironmentPanel.h"
#include "ui/panels/ParameterSlider.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace relief::ui::inline panels {
namespace {

// The light colour is linear; colour pickers show and return sRGB.
QColor toQColor(const glm::vec3& linear) {
  const auto encode = [](float v) { return core::linearToSrgb(std::clamp(v, 0.0f, 1.0f)); };
  return QColor::fromRgbF(encode(linear.r), encode(linear.g), encode(linear.b));
}

// The light's direction as the controls offer it (whole degrees, typed or dragged).
const core::OptionSpec& azimuthSpec() {
  static const core::OptionSpec spec = core::integerOption(
      "azimuth", "Azimuth", "degrees", 0, 359, 75,
      "Direction the light comes from, around the vertical axis (0 = the +Z side). Ctrl+drag "
      "in the viewport too; Shift+drag here for fine steps.");
  return spec;
}
const core::OptionSpec& elevationSpec() {
  static const core::OptionSpec spec = core::integerOption(
      "elevation", "Elevation", "degrees", 0, 90, 35,
      "Height of the light above the horizon (90 = overhead). Shift+drag for fine steps.");
  return spec;
}
constexpr int kLowestElevation = -90;  // with "Below the horizon"

glm::vec3 toLinear(const QColor& color) {
  return glm::vec3(core::srgbToLinear(float(color.redF())),
                   core::srgbToLinear(float(color.greenF())),
                   core::srgbToLinear(float(color.blueF())));
}

}  // namespace

LightPanel::LightPanel(ViewDocument* view, QWidget* parent)
    : QWidget(parent),
      m_view(view),
      m_azimuth(new ParameterSlider(azimuthSpec())),
      m_elevation(new ParameterSlider(elevationSpec())),
      m_belowHorizon(new QCheckBox(tr("Below the horizon"))),
      m_belowHorizonWarning(new QLabel),
      m_intensity(new QDoubleSpinBox),
      m_ambient(new QDoubleSpinBox),
      m_color(new QPushButton),
      m_exposure(new QDoubleSpinBox),
      m_toneMapper(new QComboBox),
      m_environment(new EnvironmentPanel(view)) {
  auto* column = new QVBoxLayout(this);
  auto* form = new QFormLayout;
  column->addLayout(form);
  auto* environmentGroup = new QGroupBox(tr("Environment (pbr light, background)"));
  auto* environmentColumn = new QVBoxLayout(environmentGroup);
  environmentColumn->addWidget(m_environment);
  column->addWidget(environmentGroup);
  column->addStretch(1);
  m_azimuth->spinBox()->setSuffix(QStringLiteral("°"));
  m_elevation->spinBox()->setSuffix(QStringLiteral("°"));
  m_belowHorizon->setToolTip(
      tr("Let the elevation go below 0: the light then comes from under the surface, which "
         "leaves it unlit (and the self-shadow view black)."));
  m_belowHorizonWarning->setWordWrap(true);
  m_belowHorizonWarning->setText(
      tr("The light is below the horizon: the surface is unlit and fully self-shadowed."));
  m_belowHorizonWarning->setStyleSheet(QStringLiteral("color: #e0a040"));
  m_belowHorizonWarning->hide();
  m_intensity->setRange(0.0, 8.0);
  m_intensity->setSingleStep(0.1);
  m_intensity->setToolTip(tr("Multiplier on the light colour (linear)."));
  m_ambient->setRange(0.0, 1.0);
  m_ambient->setSingleStep(0.02);
  m_ambient->setToolTip(
      tr("Classic shading: light without direction, a fraction of the colour map, scaled by "
         "the AO map. PBR shading takes it from the environment instead."));
  m_exposure->setRange(core::DisplayTransform::kMinExposureEv,
                       core::DisplayTransform::kMaxExposureEv);
  m_exposure->setSingleStep(0.5);
  m_exposure->setDecimals(1);
  m_exposure->setSuffix(tr(" EV"));
  m_exposure->setToolTip(tr("Exposure of the shaded view in stops: +1 doubles the brightness."));
  for (core::ToneMapper mapper : core::allToneMappers()) {
    m_toneMapper->addItem(toQString(core::toneMapperLabel(mapper)),
                          toQString(core::toneMapperName(mapper)));
  }
  m_toneMapper->setToolTip(
      tr("How radiance above 1 is shown. None clips it. Khronos PBR Neutral keeps colours below "
         "0.76 as they are and rolls highlights off smoothly toward white. ACES filmic is the "
         "film look most engines ship: more contrast, highlights that shift toward white."));
  m_color->setToolTip(tr("Colour of the light."));
  form->addRow(tr("Azimuth"), m_azimuth);
  form->addRow(tr("Elevation"), m_elevation);
  form->addRow(QString(), m_belowHorizon);
  form->addRow(m_belowHorizonWarning);
  form->addRow(tr("Colour"), m_color);
  form->addRow(tr("Intensity"), m_intensity);
  form->addRow(tr("Ambient"), m_ambient);
  form->addRow(tr("Exposure"), m_exposure);
  form->addRow(tr("Tone mapping"), m_toneMapper);

  // Typed values are applied when confirmed (Enter, focus out), not digit by digit: each
  // application is an undo step.
  for (QDoubleSpinBox* box : {m_intensity, m_ambient, m_exposure})
    box->setKeyboardTracking(false);
  for (ParameterSlider* slider : {m_azimuth, m_elevation}) {
    connect(slider, &ParameterSlider::dragStarted, this,
            [this] { m_dragEdit = m_view->beginInteractiveEdit(); });
    connect(slider, &ParameterSlider::valueEdited, this,
            [this](double, bool dragging) { applyLight(dragging); });
  }
  connect(m_belowHorizon, &QCheckBox::toggled, this, &LightPanel::allowBelowHorizon);
  connect(m_intensity, &QDoubleSpinBox::valueChanged, this, [this] { applyLight(); });
  connect(m_ambient, &QDoubleSpinBox::valueChanged, this, [this] { applyLight(); });
  connect(m_color, &QPushButton::clicked, this, &LightPanel::chooseColor);
  connect(m_exposure, &QDoubleSpinBox::valueChanged, this, &LightPanel::applyDisplay);
  connect(m_toneMapper, &QComboBox::currentIndexChanged, this, &LightPanel::applyDisplay);
  connect(view, &ViewDocument::lightChanged, this, &LightPanel::showLight);
  connect(view, &ViewDocument::displayChanged, this, &LightPanel::showLight);
  connect(view, &ViewDocument::lightBelowHorizonAllowedChanged, this, [this](bool allowed) {
    const QSignalBlocker block(m_belowHorizon);
    m_belowHorizon->setChecked(allowed);
    m_elevation->setRange(allowed ? kLowestElevation : elevationSpec().minimum,
                          elevationSpec().maximum);
  });
  showLight();
}

QSlider* LightPanel::azimuthSlider() const {
  return m_azimuth->slider();
}

QSlider* LightPanel::elevationSlider() const {
  return m_elevation->slider();
}

void LightPanel::showLight() {
  const core::DirectionalLight& light = m_view->light();
  // A light a preset or the CLI put below the horizon is shown as it is.
  if (light.elevationDeg < -0.5f)
    m_view->setLightBelowHorizonAllowed(true);
  m_belowHorizonWarning->setVisible(light.elevationDeg < 0.0f);
  const QSignalBlocker blockIntensity(m_intensity), blockAmbient(m_ambient),
      blockExposure(m_exposure), blockToneMapper(m_toneMapper);
  m_azimuth->setValue(double((int(std::lround(light.azimuthDeg)) % 360 + 360) % 360));
  m_elevation->setValue(double(std::lround(light.elevationDeg)));
  m_intensity->setValue(light.intensity);
  m_ambient->setValue(light.ambient);
  const core::DisplayTransform& display = m_view->display();
  m_exposure->setValue(display.exposureEv);
  m_toneMapper->setCurrentIndex(
      m_toneMapper->findData(toQString(core::toneMapperName(display.toneMapper))));
  const QColor color = toQColor(light.color);
  m_color->setText(color.name());
  m_color->setStyleSheet(QStringLiteral("background-color: %1; color: %2")
                             .arg(color.name(), color.lightnessF() > 0.5 ? "black" : "white"));
}

void LightPanel::applyLight(bool dragging) {
  core::DirectionalLight light = m_view->light();
  light.azimuthDeg = float(m_azimuth->value());
  light.elevationDeg = float(m_elevation->value());
  m_belowHorizonWarning->setVisible(light.elevationDeg < 0.0f);
  light.intensity = float(m_intensity->value());
  light.ambient = float(m_ambient->value());
  m_view->setLight(light, dragging ? m_dragEdit : 0);
}

void LightPanel::applyDisplay() {
  core::DisplayTransform display;
  display.exposureEv = float(m_exposure->value());
  display.toneMapper = core::findToneMapper(m_toneMapper->currentData().toString().toStdString())
                           .value_or(core::ToneMapper::None);
  m_view->setDisplay(display);
}

void LightPanel::allowBelowHorizon(bool allowed) {
  m_elevation->setRange(allowed ? kLowestElevation : elevationSpec().minimum,
                        elevationSpec().maximum);
  m_view->setLightBelowHorizonAllowed(allowed);
  if (!allowed && m_view->light().elevationDeg < 0.0f)
    applyLight();  // the clamped elevation
}

void LightPanel::chooseColor() {
  const QColor chosen =
      QColorDialog::getColor(toQColor(m_view->light().color), this, tr("Light colour"));
  if (!chosen.isValid())
    return;
  core::DirectionalLight light = m_view->light();
  light.color = toLinear(chosen);
  m_view->setLight(light);
}

}  // namespace relief::ui::inline panels
