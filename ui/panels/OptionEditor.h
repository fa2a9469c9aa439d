// Controls for OptionSpecs: a slider with a spin box for numbers, a check box for switches, a
// combo box for choices, with the spec's description, unit and range as the tooltip. The
// material's parameter panel and the Generate panel build their controls here.
#pragma once

#include "core/base/OptionSpec.h"

#include <QWidget>

#include <functional>

namespace relief::ui::inline panels {

struct OptionEdit {
  double value = 0.0;
  bool dragging = false;     // a slider is held down: more values will follow
  bool dragStarted = false;  // the first value of a drag
};

// `onEdit` is called for every user change (never for setOptionEditorValue).
QWidget* createOptionEditor(const core::OptionSpec& spec,
                            std::function<void(const OptionEdit&)> onEdit,
                            QWidget* parent = nullptr);

// Shows a value without calling onEdit.
void setOptionEditorValue(QWidget* editor, double value);

}  // namespace relief::ui::inline panels
