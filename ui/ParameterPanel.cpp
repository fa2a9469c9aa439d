// ParameterPanel; see ParameterPanel.h.
#include "ui/ParameterPanel.h"

#include "ui/MaterialDocument.h"
#include "ui/OptionEditor.h"
#include "ui/ParameterSlider.h"
#include "ui/QtText.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <map>

namespace relief::ui {
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
  if (id == core::ParamId::ShadowMode)
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
  using core::ParamId;
  const core::Material& material = m_document->material();
  const core::Technique technique = material.technique();
  const bool marching = core::isMarchingTechnique(technique);
  const auto shadowMode = core::ShadowMode(int(material.parameter(ParamId::ShadowMode)));
  const bool shadows = shadowMode != core::ShadowMode::Off;
  const auto relevant = [&](ParamId id) {
    switch (id) {
      case ParamId::MinSamples:
      case ParamId::MaxSamples:
        return marching;
      case ParamId::RefinementSteps:
        return technique == core::Technique::Relief;
      case ParamId::ShadowStrength:
      case ParamId::ShadowSamples:
      case ParamId::ShadowLimit:
        return shadows;
      case ParamId::ShadowSoftness:
        return shadowMode == core::ShadowMode::Soft;
      default:
        return true;
    }
  };
  for (const core::ParameterSpec& spec : core::allParameters()) {
    const bool on = relevant(spec.id);
    m_editors[std::size_t(spec.id)]->setEnabled(on);
    m_labels[std::size_t(spec.id)]->setEnabled(on);
  }
}

}  // namespace relief::ui
