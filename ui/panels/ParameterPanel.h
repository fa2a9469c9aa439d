// ParameterPanel: the technique and one control per material parameter, built from core's
// parameter table (sliders with spin boxes, check boxes, combo boxes) with tooltips stating
// units and ranges. Edits go through the document; document changes (undo) flow back.
#pragma once

#include "core/material/Parameters.h"
#include "ui/Forward.h"

#include <QWidget>

#include <array>

class QComboBox;

namespace relief::ui::inline panels {

class ParameterPanel : public QWidget {
  Q_OBJECT

 public:
  explicit ParameterPanel(MaterialDocument* document, QWidget* parent = nullptr);

  // The control for a parameter: a ParameterSlider, QCheckBox or QComboBox.
  QWidget* editor(core::ParamId id) const { return m_editors[std::size_t(id)]; }
  QComboBox* techniqueBox() const { return m_technique; }

 private:
  QWidget* createEditor(const core::ParameterSpec& spec);
  void showValue(core::ParamId id);
  void showAll();
  // Greys out what the current technique and shadow mode do not use (the tooltip says why).
  void updateRelevance();

  MaterialDocument* m_document;
  QComboBox* m_technique;
  std::array<QWidget*, core::kParamCount> m_editors{};
  std::array<QWidget*, core::kParamCount> m_labels{};
  int m_currentDrag = 0;
};

}  // namespace relief::ui::inline panels
