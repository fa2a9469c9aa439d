// EnvironmentPanel; see EnvironmentPanel.h.
#include "ui/panels/EnvironmentPanel.h"

#include "core/shading/EnvironmentMaps.h"
#include "ui/QtText.h"
#include "ui/document/ViewDocument.h"
#include "ui/panels/ParameterSlider.h"
#include "ui/tasks/BackgroundTask.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QMessageBox>
#include <QSignalBlocker>

#include <cmath>

namespace relief::ui::inline panels {
namespace {

// The source combo's last item opens the file dialog; its data is empty.
const QString kChooseFileData;

const core::OptionSpec& rotationSpec() {
  static const core::OptionSpec spec =
      core::integerOption("rotation", "Rotation", "degrees", -180, 180, 0,
                          "Turns the environment about the vertical axis. Shift+drag for fine "
                          "steps.");
  return spec;
}

}  // namespace

EnvironmentPanel::EnvironmentPanel(ViewDocument* view, QWidget* parent)
    : QWidget(parent),
      m_view(view),
      m_loader(new BackgroundTask(this)),
      m_source(new QComboBox),
      m_intensity(new QDoubleSpinBox),
      m_rotation(new ParameterSlider(rotationSpec())),
      m_background(new QComboBox) {
  auto* form = new QFormLayout(this);
  form->setContentsMargins(0, 0, 0, 0);
  for (core::BuiltInEnvironment environment : core::allBuiltInEnvironments()) {
    m_source->addItem(toQString(core::builtInEnvironmentLabel(environment)),
                      toQString(core::builtInEnvironmentName(environment)));
  }
  m_source->addItem(tr("File…"), kChooseFileData);
  m_source->setToolTip(
      tr("Where pbr shading's reflections and ambient light come from: a built-in, or an "
         "equirectangular (latitude-longitude) EXR or Radiance HDR file."));
  m_intensity->setRange(0.0, core::Environment::kMaxIntensity);
  m_intensity->setSingleStep(0.1);
  m_intensity->setToolTip(tr("Multiplier on the environment's radiance."));
  m_rotation->spinBox()->setSuffix(QStringLiteral("°"));
  for (core::Background background : core::allBackgrounds()) {
    m_background->addItem(toQString(core::backgroundLabel(background)),
                          toQString(core::backgroundName(background)));
  }
  m_background->setToolTip(
      tr("Behind the material: a plain dark gradient (neutral for judging colour), the "
         "environment, or the environment blurred as a rough surface reflects it."));
  form->addRow(tr("Environment"), m_source);
  form->addRow(tr("Intensity"), m_intensity);
  form->addRow(tr("Rotation"), m_rotation);
  form->addRow(tr("Background"), m_background);

  connect(m_source, &QComboBox::activated, this, &EnvironmentPanel::sourceChosen);
  m_intensity->setKeyboardTracking(false);  // a typed value is one edit, applied on Enter
  connect(m_intensity, &QDoubleSpinBox::valueChanged, this, [this] { applyEnvironment(); });
  connect(m_rotation, &ParameterSlider::dragStarted, this,
          [this] { m_dragEdit = m_view->beginInteractiveEdit(); });
  connect(m_rotation, &ParameterSlider::valueEdited, this,
          [this](double, bool dragging) { applyEnvironment(dragging); });
  connect(m_background, &QComboBox::currentIndexChanged, this, [this] { applyEnvironment(); });
  connect(view, &ViewDocument::environmentChanged, this, &EnvironmentPanel::showEnvironment);
  showEnvironment();
}

EnvironmentPanel::~EnvironmentPanel() = default;

void EnvironmentPanel::showEnvironment() {
  const core::Environment& environment = m_view->environment();
  const QSignalBlocker blockSource(m_source), blockIntensity(m_intensity),
      blockBackground(m_background);
  const QString source = QString::fromStdString(environment.source);
  int index = m_source->findData(source);
  if (index < 0)
    index = fileItem(source);
  m_source->setCurrentIndex(index);
  m_shownIndex = index;
  m_intensity->setValue(environment.intensity);
  m_rotation->setValue(double(std::lround(environment.rotationDeg)));
  m_background->setCurrentIndex(
      m_background->findData(toQString(core::backgroundName(environment.background))));
}

void EnvironmentPanel::applyEnvironment(bool dragging) {
  core::Environment environment = m_view->environment();
  environment.intensity = float(m_intensity->value());
  environment.rotationDeg = float(m_rotation->value());
  environment.background =
      core::findBackground(m_background->currentData().toString().toStdString())
          .value_or(core::Background::Color);
  m_view->setEnvironment(environment, dragging ? m_dragEdit : 0);
}

void EnvironmentPanel::sourceChosen(int index) {
  const QString chosen = m_source->itemData(index).toString();
  if (chosen == kChooseFileData) {
    m_source->setCurrentIndex(m_shownIndex);  // until a file is chosen and read
    chooseFile();
    return;
  }
  if (core::findBuiltInEnvironment(chosen.toStdString())) {
    core::Environment environment = m_view->environment();
    environment.source = chosen.toStdString();
    m_view->setEnvironment(environment);
    return;
  }
  loadFile(chosen);  // a file chosen before: read again (it may have changed or gone)
}

void EnvironmentPanel::chooseFile() {
  const QString path = QFileDialog::getOpenFileName(
      this, tr("Load environment"), QString(), tr("HDR environments (*.exr *.hdr);;All files (*)"));
  if (!path.isEmpty())
    loadFile(path);
}

void EnvironmentPanel::loadFile(const QString& path) {
  const std::string source = path.toStdString();
  using Loaded = core::Result<std::shared_ptr<const core::Image>>;
  m_loader->run<Loaded>(
      [source](const core::WorkControl&) { return core::environmentRadiance(source); },
      [this, path](Loaded&& loaded) {
        if (!loaded) {
          const QString message = QString::fromStdString(loaded.error());
          showEnvironment();
          QMessageBox::warning(this, tr("Relief: environment not loaded"), message);
          Q_EMIT fileLoaded(false, message);
          return;
        }
        core::Environment environment = m_view->environment();
        environment.source = path.toStdString();
        m_view->setEnvironment(environment);
        Q_EMIT fileLoaded(true, QString());
      });
}

int EnvironmentPanel::fileItem(const QString& path) {
  const int existing = m_source->findData(path);
  if (existing >= 0)
    return existing;
  const int position = m_source->count() - 1;  // before "File…"
  m_source->insertItem(position, QFileInfo(path).fileName(), path);
  m_source->setItemData(position, path, Qt::ToolTipRole);
  return position;
}

}  // namespace relief::ui::inline panels
