// GeneratePanel; see GeneratePanel.h.
#include "ui/panels/GeneratePanel.h"

#include "core/image/ImageIO.h"
#include "renderer/ImageConversion.h"
#include "ui/QtText.h"
#include "ui/compare/ImagePairView.h"
#include "ui/document/MaterialDocument.h"
#include "ui/panels/OptionEditor.h"
#include "ui/tasks/GeneratorRunner.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

namespace relief::ui::inline panels {
namespace {

constexpr int kViewSize = 512;

}  // namespace

GeneratePanel::GeneratePanel(MaterialDocument* document, QWidget* parent)
    : QWidget(parent),
      m_document(document),
      m_runner(new GeneratorRunner(this)),
      m_generator(new QComboBox),
      m_form(new QFormLayout),
      m_destination(new QComboBox),
      m_adjustMaterial(new QCheckBox),
      m_view(new ImagePairView),
      m_status(new QLabel),
      m_progress(new QProgressBar),
      m_cancel(new QPushButton(tr("Cancel"))),
      m_apply(new QPushButton(tr("Apply"))),
      m_save(new QPushButton(tr("Save…"))) {
  auto* outer = new QVBoxLayout(this);
  auto* top = new QFormLayout;
  for (const core::GeneratorInfo& info : core::allGenerators()) {
    m_generator->addItem(toQString(info.label), toQString(info.name));
  }
  m_generator->setObjectName(QStringLiteral("generator"));
  m_generator->setToolTip(tr("What to make, and from what (the CLI's relief-cli generate)."));
  top->addRow(tr("Generate"), m_generator);
  outer->addLayout(top);
  m_form->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
  outer->addLayout(m_form);
  outer->addWidget(m_view, 1);
  m_status->setWordWrap(true);
  outer->addWidget(m_status);

  auto* progressRow = new QHBoxLayout;
  m_progress->setRange(0, 100);
  progressRow->addWidget(m_progress, 1);
  progressRow->addWidget(m_cancel);
  outer->addLayout(progressRow);

  auto* destination = new QFormLayout;
  for (core::MapSlot slot : core::kAllMapSlots)
    m_destination->addItem(toQString(core::mapSlotLabel(slot)));
  m_destination->setToolTip(tr("The map slot Apply puts the result into."));
  destination->addRow(tr("Into"), m_destination);
  destination->addRow(QString(), m_adjustMaterial);
  outer->addLayout(destination);
  auto* buttons = new QHBoxLayout;
  m_apply->setToolTip(tr("Put the full-size result into the material (one undo step)."));
  m_save->setToolTip(tr("Write the full-size result to a file: 16-bit PNG/TIFF, float EXR."));
  buttons->addWidget(m_save);
  buttons->addStretch(1);
  buttons->addWidget(m_apply);
  outer->addLayout(buttons);

  connect(m_generator, &QComboBox::activated, this,
          [this](int index) { setGenerator(core::allGenerators()[std::size_t(index)].kind); });
  connect(m_cancel, &QPushButton::clicked, this, [this] {
    m_runner->cancel();
    m_progress->setValue(0);
    m_status->setText(tr("Cancelled. Change an option to run again."));
  });
  connect(m_apply, &QPushButton::clicked, this, &GeneratePanel::apply);
  connect(m_save, &QPushButton::clicked, this, &GeneratePanel::saveResult);
  connect(m_runner, &GeneratorRunner::previewReady, this,
          [this](const core::GeneratedMap& map) { showResult(map, true); });
  connect(m_runner, &GeneratorRunner::resultReady, this, [this](const core::GeneratedMap& map) {
    m_result = map;
    m_progress->setValue(100);
    showResult(map, false);
    Q_EMIT resultAvailable();
  });
  connect(m_runner, &GeneratorRunner::progress, this,
          [this](double fraction) { m_progress->setValue(int(fraction * 100.0)); });
  connect(m_runner, &GeneratorRunner::failed, this,
          [this](const QString& message) { m_status->setText(message); });
  // New source maps (loaded, generated, undone) mean a new result.
  connect(m_document, &MaterialDocument::mapChanged, this, &GeneratePanel::regenerate);
  connect(m_document, &MaterialDocument::materialReset, this, &GeneratePanel::regenerate);
  setGenerator(core::GeneratorKind::Normal);
}

QWidget* GeneratePanel::optionEditor(const std::string& name) const {
  const int index = core::findGeneratorOption(m_kind, name);
  return index >= 0 ? m_optionEditors[std::size_t(index)] : nullptr;
}

void GeneratePanel::setGenerator(core::GeneratorKind kind) {
  m_kind = kind;
  m_generator->setCurrentIndex(int(kind));
  m_values = core::defaultGeneratorValues(kind);
  rebuild();
  regenerate();
}

void GeneratePanel::rebuild() {
  while (m_form->rowCount() > 0)
    m_form->removeRow(0);
  m_inputBoxes.clear();
  m_optionEditors.clear();
  const core::GeneratorInfo& info = core::generatorInfo(m_kind);
  for (const core::GeneratorInput& input : info.inputs) {
    auto* box = new QComboBox;
    for (core::MapSlot slot : core::kAllMapSlots)
      box->addItem(toQString(core::mapSlotLabel(slot)));
    // An optional input may be left out (its neutral value stands in); the last item.
    if (input.optional)
      box->addItem(tr("None (neutral value)"));
    box->setCurrentIndex(int(input.defaultSlot));
    box->setToolTip(
        input.optional
            ? tr("Which of the material's maps to use as the %1; none, or an empty slot, uses its "
                 "neutral value.")
                  .arg(toQString(input.label).toLower())
            : tr("Which of the material's maps to use as the %1.")
                  .arg(toQString(input.label).toLower()));
    connect(box, &QComboBox::activated, this, &GeneratePanel::regenerate);
    m_form->addRow(toQString(input.label), box);
    m_inputBoxes.push_back(box);
  }
  for (std::size_t i = 0; i < info.options.size(); ++i) {
    const core::OptionSpec& option = info.options[i];
    QWidget* editor = createOptionEditor(option, [this, i](const OptionEdit& edit) {
      m_values[i] = edit.value;
      regenerate();
    });
    auto* label = new QLabel(toQString(option.label));
    label->setToolTip(editor->toolTip());
    m_form->addRow(label, editor);
    m_optionEditors.push_back(editor);
  }
  m_destination->setCurrentIndex(int(info.output));
  updateAdjustMaterial();
  m_adjustMaterial->setChecked(true);
  m_adjustMaterial->setText(m_kind == core::GeneratorKind::Height
                                ? tr("Set the height scale to the measured depth")
                                : tr("Read height from normal alpha, keep the relief"));
}

std::vector<std::shared_ptr<const core::Image>> GeneratePanel::currentInputs(
    QString& problem) const {
  std::vector<std::shared_ptr<const core::Image>> inputs;
  const core::GeneratorInfo& info = core::generatorInfo(m_kind);
  for (std::size_t i = 0; i < m_inputBoxes.size(); ++i) {
    const auto choice = std::size_t(m_inputBoxes[i]->currentIndex());
    if (choice >= core::kMapSlotCount) {  // "None" of an optional input
      inputs.push_back(nullptr);
      continue;
    }
    const auto slot = core::kAllMapSlots[choice];
    const std::shared_ptr<const core::Image>& image = m_document->material().map(slot).image;
    if (!image && info.inputs[i].optional) {
      inputs.push_back(nullptr);
      continue;
    }
    if (!image) {
      problem = tr("The material has no %1 map to use as the %2. Load one (Maps) or pick another.")
                    .arg(toQString(core::mapSlotLabel(slot)).toLower(),
                         toQString(info.inputs[i].label).toLower());
      return {};
    }
    inputs.push_back(image);
  }
  return inputs;
}

void GeneratePanel::regenerate() {
  m_result.reset();
  m_apply->setEnabled(false);
  m_save->setEnabled(false);
  m_progress->setValue(0);
  updateAdjustMaterial();
  QString problem;
  auto inputs = currentInputs(problem);
  showSource();
  const bool anyInput =
      std::any_of(inputs.begin(), inputs.end(), [](const auto& image) { return bool(image); });
  if (!anyInput && problem.isEmpty())
    problem = tr("The material has none of the maps this generator reads. Load one (Maps).");
  if (!anyInput) {
    m_runner->cancel();
    m_view->setRight({}, tr("Result"));
    m_status->setText(problem);
    return;
  }
  QString warning;
  const bool normalSource =
      core::generatorInfo(m_kind).inputs.front().defaultSlot == core::MapSlot::Normal ||
      (m_kind == core::GeneratorKind::Curvature &&
       m_values[std::size_t(core::findGeneratorOption(m_kind, "from"))] == 1.0);
  if (normalSource && inputs.front()) {
    if (const auto message = core::normalMapWarning(*inputs.front())) {
      warning = tr("Warning: %1.").arg(QString::fromStdString(*message));
    }
  }
  m_status->setText(warning.isEmpty() ? tr("Working…") : warning);
  m_runner->request(m_kind, std::move(inputs), m_values);
}

void GeneratePanel::showSource() {
  // The first input that has a map (pack's inputs may all be optional).
  const core::Image* image = nullptr;
  core::MapSlot slot = core::MapSlot::Color;
  for (const QComboBox* box : m_inputBoxes) {
    const auto choice = std::size_t(box->currentIndex());
    if (choice >= core::kMapSlotCount)
      continue;
    slot = core::kAllMapSlots[choice];
    image = m_document->material().image(slot);
    if (image)
      break;
  }
  if (m_inputBoxes.empty())
    return;
  m_view->setLeft(image ? renderer::makeThumbnail(*image, kViewSize) : QImage(),
                  tr("Source: %1").arg(toQString(core::mapSlotLabel(slot))));
}

void GeneratePanel::showResult(const core::GeneratedMap& map, bool preview) {
  const QString caption =
      preview ? tr("Preview") : tr("Result %1×%2").arg(map.image.width()).arg(map.image.height());
  m_view->setRight(renderer::makeThumbnail(map.image, kViewSize), caption);
  QStringList notes;
  for (const std::string& note : map.notes)
    notes << QString::fromStdString(note);
  if (!preview) {
    const bool fits = resultFitsASlot();
    m_apply->setEnabled(fits);
    m_save->setEnabled(true);
    const QString ready = fits ? tr("Ready: Apply puts it into the material.")
                               : tr("Ready: Save writes it (the material has no slot for a "
                                    "packed map in this layout).");
    m_status->setText(
        notes.isEmpty() ? ready : notes.join(QStringLiteral("; ")) + QStringLiteral(". ") + ready);
  }
}

bool GeneratePanel::resultFitsASlot() const {
  if (m_kind != core::GeneratorKind::Pack)
    return true;
  // Only height in normal alpha (the layout's first choice) goes back into a slot.
  return m_values[std::size_t(core::findGeneratorOption(m_kind, "layout"))] == 0.0;
}

void GeneratePanel::updateAdjustMaterial() {
  m_adjustMaterial->setVisible(m_kind == core::GeneratorKind::Height ||
                               (m_kind == core::GeneratorKind::Pack && resultFitsASlot()));
  m_destination->setEnabled(resultFitsASlot());
}

void GeneratePanel::apply() {
  if (!m_result)
    return;
  using core::ParamId;
  const core::Material& material = m_document->material();
  std::vector<std::pair<ParamId, double>> changes;
  if (m_adjustMaterial->isChecked() && m_adjustMaterial->isVisible()) {
    if (m_kind == core::GeneratorKind::Height && m_result->depthTexels) {
      const double scale = *m_result->depthTexels / double(m_result->image.width());
      changes = {{ParamId::HeightScale, scale}, {ParamId::HeightBias, -scale}};
    }
    if (m_kind == core::GeneratorKind::Pack) {
      changes.emplace_back(ParamId::HeightInNormalAlpha, 1.0);
      if (m_result->levels) {
        const core::HeightCompensation compensation =
            core::compensateLevels(*m_result->levels, material.parameter(ParamId::HeightScale),
                                   material.parameter(ParamId::HeightBias));
        changes.emplace_back(ParamId::HeightScale, compensation.heightScale);
        changes.emplace_back(ParamId::HeightBias, compensation.heightBias);
      }
    }
  }
  const auto slot = core::kAllMapSlots[std::size_t(m_destination->currentIndex())];
  auto image = std::make_shared<core::Image>(m_result->image);
  m_document->applyGenerated(slot, std::move(image),
                             tr("Generate %1").arg(toQString(core::generatorInfo(m_kind).label)),
                             changes);
}

void GeneratePanel::saveResult() {
  if (!m_result)
    return;
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Save generated map"), QString(),
      tr("16-bit PNG (*.png);;16-bit TIFF (*.tif);;Float EXR (*.exr)"));
  if (path.isEmpty())
    return;
  if (core::Status saved = core::saveImage(m_result->image, path.toStdString(),
                                           core::fullPrecisionFormatFor(path.toStdString()));
      !saved) {
    QMessageBox::warning(this, tr("Cannot save"), QString::fromStdString(saved.error()));
  }
}

}  // namespace relief::ui::inline panels
