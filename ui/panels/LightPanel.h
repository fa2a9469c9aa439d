// LightPanel: the directional light's azimuth and elevation, colour, intensity and ambient, the
// display's exposure and tone mapping, and the environment (EnvironmentPanel). Kept in step with
// the viewport, where Ctrl+drag moves the same light.
#pragma once

#include "ui/Forward.h"

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QPushButton;
class QSlider;

namespace relief::ui::inline panels {

class LightPanel : public QWidget {
  Q_OBJECT

 public:
  explicit LightPanel(ViewportWidget* viewport, QWidget* parent = nullptr);

  QSlider* azimuthSlider() const { return m_azimuth; }
  QSlider* elevationSlider() const { return m_elevation; }
  QDoubleSpinBox* intensityBox() const { return m_intensity; }
  QDoubleSpinBox* ambientBox() const { return m_ambient; }
  QPushButton* colorButton() const { return m_color; }
  QDoubleSpinBox* exposureBox() const { return m_exposure; }
  QComboBox* toneMapperBox() const { return m_toneMapper; }
  EnvironmentPanel* environmentPanel() const { return m_environment; }

 public Q_SLOTS:
  void showLight();  // reads the viewport's light into the controls

 private:
  void applyToViewport();
  void chooseColor();

  ViewportWidget* m_viewport;
  QSlider* m_azimuth;
  QSlider* m_elevation;
  QDoubleSpinBox* m_intensity;
  QDoubleSpinBox* m_ambient;
  QPushButton* m_color;
  QDoubleSpinBox* m_exposure;
  QComboBox* m_toneMapper;
  EnvironmentPanel* m_environment;
};

}  // namespace relief::ui::inline panels
