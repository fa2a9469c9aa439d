// ParameterPanel; see ParameterPanel.h.
#include "ui/ParameterPanel.h"

#include "ui/MaterialDocument.h"
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
    editor->setObjectName(toQString(spec.name));
    editor->setToolTip(toQString(core::describeOption(spec)));
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
  switch (spec.kind) {
    case core::ParamKind::Bool: {
      auto* box = new QCheckBox;
      connect(box, &QCheckBox::toggled, this,
              [this, id](bool on) { m_document->setParameter(id, on ? 1.0 : 0.0); });
      return box;
    }
    case core::ParamKind::Choice: {
      auto* box = new QComboBox;
      for (std::string_view choice : spec.choices)
        box->addItem(toQString(choice));
      connect(box, &QComboBox::activated, this,
              [this, id](int index) { m_document->setParameter(id, double(index)); });
      return box;
    }
    case core::ParamKind::Float:
    case core::ParamKind::Int:
      break;
  }
  auto* slider = new ParameterSlider(spec);
  connect(slider, &ParameterSlider::dragStarted, this,
          [this] { m_currentDrag = m_document->beginInteractiveEdit(); });
  connect(slider, &ParameterSlider::valueEdited, this, [this, id](double value, bool dragging) {
    m_document->setParameter(id, value, dragging ? m_currentDrag : 0);
  });
  return slider;
}

void ParameterPanel::showValue(core::ParamId id) {
  if (id == core::ParamId::ShadowMode)
    updateRelevance();
  const double value = m_document->material().parameter(id);
  QWidget* editor = m_editors[std::size_t(id)];
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
