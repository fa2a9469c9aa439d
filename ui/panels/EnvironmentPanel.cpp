// EnvironmentPanel; see EnvironmentPanel.h.
#include "ui/panels/EnvironmentPanel.h"

#include "core/compression/CompressionMetrics.h"
#include "core/compression/Compressor.h"
#include "core/compression/TextureFile.h"
#include "core/shading/EnvironmentMaps.h"
#include "ui/QtText.h"
#include "ui/document/ViewDocument.h"
#include "ui/panels/ParameterSlider.h"
#include "ui/tasks/BackgroundTask.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
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
      m_background(new QComboBox),
      m_saveCompressed(new QPushButton(tr("Save as BC6H…"))),
      m_compressedNote(new QLabel) {
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
  m_saveCompressed->setObjectName(QStringLiteral("saveEnvironmentBc6h"));
  m_saveCompressed->setToolTip(
      tr("Compress the environment into BC6H (half floats, 8 bits per texel: what desktop "
         "engines ship HDR environments as), save it as KTX2 or DDS, and light the material "
         "with it, to see what the compression costs. Undo returns to the original."));
  m_compressedNote->setWordWrap(true);
  m_compressedNote->setVisible(false);
  form->addRow(QString(), m_saveCompressed);
  form->addRow(QString(), m_compressedNote);
  connect(m_saveCompressed, &QPushButton::clicked, this, &EnvironmentPanel::chooseCompressedPath);
  // A newer load or save replaces a running save: the button comes back either way.
  connect(m_loader, &BackgroundTask::cancelled, this,
          [this] { m_saveCompressed->setEnabled(true); });

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
      this, tr("Load environment"), QString(),
      tr("HDR environments (*.exr *.hdr *.ktx2 *.dds);;All files (*)"));
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

void EnvironmentPanel::chooseCompressedPath() {
  const QString source = QString::fromStdString(m_view->environment().source);
  const QString suggested = QFileInfo(source).completeBaseName() + QStringLiteral("_bc6h.ktx2");
  const QString path = QFileDialog::getSaveFileName(this, tr("Save environment as BC6H"), suggested,
                                                    tr("KTX2, Zstandard (*.ktx2);;DDS (*.dds)"));
  if (!path.isEmpty())
    saveCompressed(path);
}

void EnvironmentPanel::saveCompressed(const QString& path) {
  struct Saved {
    qint64 bytes = 0;
    core::HdrError error;
    double seconds = 0.0;
  };
  using Outcome = core::Result<Saved>;
  const std::string source = m_view->environment().source;
  const std::string target = path.toStdString();
  // Disabling a focused button moves the focus on, and the Light dock's scroll area then jumps
  // to the widget that took it, away from the note below: let go of the focus first.
  const bool hadFocus = m_saveCompressed->hasFocus();
  m_saveCompressed->clearFocus();
  m_saveCompressed->setEnabled(false);
  m_compressedNote->setText(tr("Compressing…"));
  m_compressedNote->setVisible(true);
  m_loader->run<Outcome>(
      [source, target](const core::WorkControl& control) -> Outcome {
        core::Result<std::shared_ptr<const core::Image>> radiance =
            core::environmentRadiance(source);
        if (!radiance)
          return core::makeError(radiance.error());
        const std::optional<core::TextureContainer> container = core::containerForPath(target);
        if (!container)
          return core::makeError(target + ": the file must end in .ktx2 or .dds");
        core::CompressionSettings settings;
        settings.format = core::TextureFormat::Bc6h;
        settings.mipmaps = true;
        settings.zstdLevel = *container == core::TextureContainer::Ktx2 ? 19 : 0;
        QElapsedTimer timer;
        timer.start();
        core::Result<core::CompressedTexture> texture =
            core::compressMap(*radiance.value(), core::MapSlot::Color, settings, control);
        if (!texture)
          return core::makeError(texture.error());
        Saved saved;
        saved.seconds = double(timer.elapsed()) / 1000.0;
        if (core::Status written =
                core::saveCompressedTexture(texture.value(), target, settings.zstdLevel);
            !written)
          return core::makeError(written.error());
        // Read back as the renderer will light with it: this also puts the file in the
        // environment cache here, off the GUI thread, before the viewport asks for it.
        core::Result<std::shared_ptr<const core::Image>> shipped =
            core::environmentRadiance(target);
        if (!shipped)
          return core::makeError(shipped.error());
        saved.error = core::measureHdrError(*radiance.value(), *shipped.value());
        saved.bytes = QFileInfo(QString::fromStdString(target)).size();
        return saved;
      },
      [this, path, hadFocus](Outcome&& outcome) {
        m_saveCompressed->setEnabled(true);
        if (hadFocus)
          m_saveCompressed->setFocus();
        if (!outcome) {
          const QString message = QString::fromStdString(outcome.error());
          m_compressedNote->setText(tr("Not saved: %1").arg(message));
          QMessageBox::warning(this, tr("Relief: environment not saved"), message);
          Q_EMIT compressedSaved(false, message);
          return;
        }
        core::Environment environment = m_view->environment();
        environment.source = path.toStdString();
        m_view->setEnvironment(environment);
        const QString message =
            tr("%1: %2 KB, exposure PSNR %3 dB, mean error %4 stops (%5 s). Lighting the "
               "material now; Undo returns to the original.")
                .arg(QFileInfo(path).fileName())
                .arg(double(outcome->bytes) / 1024.0, 0, 'f', 0)
                .arg(outcome->error.exposurePsnr, 0, 'f', 1)
                .arg(outcome->error.meanLog2Error, 0, 'f', 4)
                .arg(outcome->seconds, 0, 'f', 1);
        m_compressedNote->setText(message);
        Q_EMIT compressedSaved(true, message);
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
