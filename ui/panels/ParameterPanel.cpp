// ParameterPanel; see ParameterPanel.h.
#include "ui/panels/ParameterPanel.h"

#include "ui/QtText.h"
#include "ui/document/MaterialDocument.h"
#include "ui/panels/OptionEditor.h"
#include "ui/panels/ParameterSlider.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <map>

namespace relief::ui::inline panels {
ParameterPanel::ParameterPanel(MaterialDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_technique(new QComboBox) {
  auto* outer = new QVBoxLayout(this);
  auto* form = new QFormLayout;
  form->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
  outer->addLayout(form);
  std::map<std::string_view, QFormLayout*> groups;

  for (core::Technique technique : core::allTechniques()) {
    m_technique->addItem(toQString(core::techniqueLabel(technique)),
                         toQString(core::techniqueName(technique)));
  }
  m_technique->setToolTip(tr("How the relief is rendered (the CLI's --technique)."));
  form->addRow(tr("Technique"), m_technique);
  connect(m_technique, &QComboBox::activated, this, [this](int index) {
    m_document->setTechnique(core::allTechniques()[std::size_t(index)]);
  });

  // One box per group, in the table's order.
  for (const core::ParameterSpec& spec : core::allParameters()) {
    QFormLayout*& group = groups[spec.group];
    if (!group) {
      auto* box = new QGroupBox(toQString(spec.group));
      group = new QFormLayout(box);
      group->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
      outer->addWidget(box);
    }
    QWidget* editor = createEditor(spec);
    m_editors[std::size_t(spec.id)] = editor;
    if (auto* check = qobject_cast<QCheckBox*>(editor)) {
      // A switch names itself across the row, so its long label ("Height in normal map
      // alpha") does not widen the label column and squeeze every slider.
      check->setText(toQString(spec.label));
      check->setSizePolicy(QSizePolicy::Maximum, QSizePolicy::Fixed);  // clicks beside it miss
      m_labels[std::size_t(spec.id)] = check;
      group->addRow(check);
      continue;
    }
    auto* label = new QLabel(toQString(spec.label));
    label->setToolTip(editor->toolTip());
    m_labels[std::size_t(spec.id)] = label;
    group->addRow(label, editor);
  }

  auto* resetButton = new QPushButton(tr("Reset to defaults"));
  resetButton->setToolTip(tr("Set every parameter back to its default (undoable)."));
  connect(resetButton, &QPushButton::clicked, m_document, &MaterialDocument::resetParameters);
  outer->addWidget(resetButton);
  outer->addStretch(1);

  connect(m_document, &MaterialDocument::parameterChanged, this, &ParameterPanel::showValue);
  connect(m_document, &MaterialDocument::materialReset, this, &ParameterPanel::showAll);
  connect(m_document, &MaterialDocument::techniqueChanged, this, &ParameterPanel::showAll);
  showAll();
}

QWidget* ParameterPanel::createEditor(const core::ParameterSpec& spec) {
  const core::ParamId id = spec.id;
  return createOptionEditor(spec, [this, id](const OptionEdit& edit) {
    if (edit.dragStarted)
      m_currentDrag = m_document->beginInteractiveEdit();
    m_document->setParameter(id, edit.value, edit.dragging ? m_currentDrag : 0);
  });
}

void ParameterPanel::showValue(core::ParamId id) {
  if (id == core::ParamId::ShadowMode || id == core::ParamId::Shading)
    updateRelevance();
  setOptionEditorValue(m_editors[std::size_t(id)], m_document->material().parameter(id));
}

void ParameterPanel::showAll() {
  {
    const QSignalBlocker block(m_technique);
    m_technique->setCurrentIndex(int(m_document->material().technique()));
  }
  for (const core::ParameterSpec& spec : core::allParameters())
    showValue(spec.id);
  updateRelevance();
}

void ParameterPanel::updateRelevance() {
  const core::Material& material = m_document->material();
  const auto shadows = core::ShadowMode(int(material.parameter(core::ParamId::ShadowMode)));
  const auto shading = core::ShadingModel(int(material.parameter(core::ParamId::Shading)));
  for (const core::ParameterSpec& spec : core::allParameters()) {
    const bool on = core::parameterInUse(spec, material.technique(), shadows, shading);
    m_editors[std::size_t(spec.id)]->setEnabled(on);
    m_labels[std::size_t(spec.id)]->setEnabled(on);
  }
}

}  // namespace relief::ui::inline panels
