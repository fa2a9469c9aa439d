// LightPanel: the directional light's azimuth and elevation, colour, intensity and ambient.
// Kept in step with the viewport, where Ctrl+drag moves the same light.
#pragma once

#include "ui/Forward.h"

#include <QWidget>

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
};

}  // namespace relief::ui::inline panels
