// OptionEditor; see OptionEditor.h.
#include "ui/panels/OptionEditor.h"

#include "ui/QtText.h"
#include "ui/panels/ParameterSlider.h"

#include <QCheckBox>
#include <QComboBox>
#include <QSignalBlocker>

#include <memory>

namespace relief::ui::inline panels {

QWidget* createOptionEditor(const core::OptionSpec& spec,
                            std::function<void(const OptionEdit&)> onEdit, QWidget* parent) {
  QWidget* editor = nullptr;
  switch (spec.kind) {
    case core::ParamKind::Bool: {
      auto* box = new QCheckBox(parent);
      QObject::connect(box, &QCheckBox::toggled, box, [onEdit](bool on) {
        onEdit({on ? 1.0 : 0.0, false, false});
      });
      editor = box;
      break;
    }
    case core::ParamKind::Choice: {
      auto* box = new QComboBox(parent);
      for (std::string_view choice : spec.choices)
        box->addItem(toQString(choice));
      QObject::connect(box, &QComboBox::activated, box, [onEdit](int index) {
        onEdit({double(index), false, false});
      });
      editor = box;
      break;
    }
    case core::ParamKind::Float:
    case core::ParamKind::Int: {
      auto* slider = new ParameterSlider(spec, parent);
      auto starting = std::make_shared<bool>(false);
      QObject::connect(slider, &ParameterSlider::dragStarted, slider,
                       [starting] { *starting = true; });
      QObject::connect(slider, &ParameterSlider::valueEdited, slider,
                       [onEdit, starting](double value, bool dragging) {
                         onEdit({value, dragging, dragging && *starting});
                         if (dragging)
                           *starting = false;
                       });
      editor = slider;
      break;
    }
  }
  editor->setObjectName(toQString(spec.name));
  editor->setToolTip(QString::fromStdString(core::describeOption(spec)));
  setOptionEditorValue(editor, spec.defaultValue);
  return editor;
}

void setOptionEditorValue(QWidget* editor, double value) {
  if (auto* slider = qobject_cast<ParameterSlider*>(editor)) {
    slider->setValue(value);
  } else if (auto* check = qobject_cast<QCheckBox*>(editor)) {
    const QSignalBlocker block(check);
    check->setChecked(value != 0.0);
  } else if (auto* combo = qobject_cast<QComboBox*>(editor)) {
    const QSignalBlocker block(combo);
    combo->setCurrentIndex(int(value));
  }
}

}  // namespace relief::ui::inline panels
