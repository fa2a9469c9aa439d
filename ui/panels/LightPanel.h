// LightPanel: the directional light's azimuth and elevation, colour, intensity and ambient, the
// display's exposure and tone mapping, and the environment (EnvironmentPanel): controls of the
// view document, which the viewport renders and where Ctrl+drag moves the same light. Each change
// is an undo step; a slider drag is one. The elevation stays between the horizon
// and overhead unless "Below the horizon" is ticked (a light from below leaves the surface
// unlit and the self-shadow view black, which is rarely what an artist wants by accident).
#pragma once

#include "ui/Forward.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSlider;

namespace relief::ui::inline panels {

class LightPanel : public QWidget {
  Q_OBJECT

 public:
  explicit LightPanel(ViewDocument* view, QWidget* parent = nullptr);

  QSlider* azimuthSlider() const;
  QSlider* elevationSlider() const;
  ParameterSlider* azimuthControl() const { return m_azimuth; }
  ParameterSlider* elevationControl() const { return m_elevation; }
  QCheckBox* belowHorizonBox() const { return m_belowHorizon; }
  QLabel* belowHorizonWarning() const { return m_belowHorizonWarning; }
  QDoubleSpinBox* intensityBox() const { return m_intensity; }
  QDoubleSpinBox* ambientBox() const { return m_ambient; }
  QPushButton* colorButton() const { return m_color; }
  QDoubleSpinBox* exposureBox() const { return m_exposure; }
  QComboBox* toneMapperBox() const { return m_toneMapper; }
  EnvironmentPanel* environmentPanel() const { return m_environment; }

 public Q_SLOTS:
  void showLight();  // reads the view document's light and display into the controls

 private:
  // The controls' light as an edit of the view document; a slider drag merges into one step.
  void applyLight(bool dragging = false);
  void applyDisplay();
  void chooseColor();
  void allowBelowHorizon(bool allowed);

  ViewDocument* m_view;
  int m_dragEdit = 0;  // the view document's interactive edit of the slider being dragged
  ParameterSlider* m_azimuth;
  ParameterSlider* m_elevation;
  QCheckBox* m_belowHorizon;
  QLabel* m_belowHorizonWarning;
  QDoubleSpinBox* m_intensity;
  QDoubleSpinBox* m_ambient;
  QPushButton* m_color;
  QDoubleSpinBox* m_exposure;
  QComboBox* m_toneMapper;
  EnvironmentPanel* m_environment;
};

}  // namespace relief::ui::inline panels
