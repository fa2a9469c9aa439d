// MapCheckBanner; see MapCheckBanner.h.
#include "ui/panels/MapCheckBanner.h"

#include "ui/document/MaterialDocument.h"
#include "ui/tasks/BackgroundTask.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include <memory>
#include <optional>

namespace relief::ui::inline panels {
namespace {

QString fileNameOf(const core::MaterialMap& map, const QString& fallback) {
  return map.sourcePath.empty() ? fallback
                                : QFileInfo(QString::fromStdString(map.sourcePath)).fileName();
}

}  // namespace

MapCheckBanner::MapCheckBanner(MaterialDocument* document, QWidget* parent)
    : QFrame(parent), m_document(document), m_task(new BackgroundTask(this)) {
  setObjectName(QStringLiteral("mapCheckBanner"));
  setFrameShape(QFrame::StyledPanel);
  // Amber on the dark theme: a warning, not an error (the maps still load and render).
  setStyleSheet(
      QStringLiteral("#mapCheckBanner { background: #4a3b12; border: 1px solid #a07d1c; }"));
  m_text = new QLabel;
  m_text->setWordWrap(true);
  m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
  m_flipY = new QPushButton;
  m_flipY->setObjectName(QStringLiteral("mapCheckFlipY"));
  m_invertHeight = new QPushButton;
  m_invertHeight->setObjectName(QStringLiteral("mapCheckInvertHeight"));
  auto* buttons = new QHBoxLayout;
  buttons->addStretch(1);
  buttons->addWidget(m_flipY);
  buttons->addWidget(m_invertHeight);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(m_text);
  layout->addLayout(buttons);
  // The fixes change how the material reads its maps (undoable), never the maps.
  connect(m_flipY, &QPushButton::clicked, this, [this] {
    const bool yDown = m_document->material().parameterFlag(core::ParamId::NormalYDown);
    m_document->setParameter(core::ParamId::NormalYDown, yDown ? 0.0 : 1.0);
  });
  connect(m_invertHeight, &QPushButton::clicked, this, [this] {
    const bool depth = m_document->material().parameterFlag(core::ParamId::HeightIsDepth);
    m_document->setParameter(core::ParamId::HeightIsDepth, depth ? 0.0 : 1.0);
  });
  connect(document, &MaterialDocument::mapChanged, this, [this](core::MapSlot slot) {
    if (slot == core::MapSlot::Normal || slot == core::MapSlot::Height)
      recheck();
  });
  connect(document, &MaterialDocument::parameterChanged, this, [this](core::ParamId id) {
    if (id == core::ParamId::NormalYDown || id == core::ParamId::HeightIsDepth ||
        id == core::ParamId::HeightInNormalAlpha)
      recheck();
  });
  connect(document, &MaterialDocument::materialReset, this, &MapCheckBanner::recheck);
  hide();
  recheck();
}

void MapCheckBanner::recheck() {
  const core::Material& material = m_document->material();
  const core::MaterialMap& normal = material.map(core::MapSlot::Normal);
  if (!normal.image || normal.image->channels() < 2) {
    m_task->cancel();
    hide();
    return;
  }
  std::shared_ptr<const core::Image> normalImage = normal.image;
  std::shared_ptr<const core::Image> heightImage = material.map(core::MapSlot::Height).image;
  const bool heightInAlpha =
      material.parameterFlag(core::ParamId::HeightInNormalAlpha) && normalImage->channels() == 4;
  m_task->run<std::optional<core::MapCheckResult>>(
      [normalImage, heightImage, heightInAlpha](const core::WorkControl&) {
        std::optional<core::Image> alpha;
        if (heightInAlpha)
          alpha = core::channelImage(*normalImage, 3);
        const core::Image* height = alpha ? &*alpha : heightImage.get();
        core::Result<core::MapCheckResult> result = core::checkMaps(*normalImage, height);
        if (!result && height)  // maps of different shapes: the normal map alone
          result = core::checkMaps(*normalImage, nullptr);
        return result ? std::optional(result.value()) : std::nullopt;
      },
      [this](std::optional<core::MapCheckResult>&& result) {
        if (result)
          showResult(*result);
        else
          hide();
      });
}

void MapCheckBanner::showResult(const core::MapCheckResult& result) {
  const core::Material& material = m_document->material();
  const bool yDown = material.parameterFlag(core::ParamId::NormalYDown);
  const bool depth = material.parameterFlag(core::ParamId::HeightIsDepth);
  const QString normalName = fileNameOf(material.map(core::MapSlot::Normal), tr("the normal map"));
  const QString heightName =
      material.parameterFlag(core::ParamId::HeightInNormalAlpha)
          ? tr("%1 (alpha)").arg(normalName)
          : fileNameOf(material.map(core::MapSlot::Height), tr("the height map"));
  const std::vector<std::string> findings = core::mapCheckFindings(
      result, yDown ? core::NormalConvention::DirectX : core::NormalConvention::OpenGl, depth,
      normalName.toStdString(), heightName.toStdString());
  if (findings.empty()) {
    hide();
    return;
  }
  QString text;
  for (const std::string& finding : findings)
    text += (text.isEmpty() ? QString() : QStringLiteral("\n\n")) + QString::fromStdString(finding);
  m_text->setText(text);
  const bool conventionWrong =
      result.convention && (*result.convention == core::NormalConvention::DirectX) != yDown;
  m_flipY->setVisible(conventionWrong);
  m_flipY->setText(yDown ? tr("Read as OpenGL (+Y up)") : tr("Read as DirectX (+Y down)"));
  const bool senseWrong = result.heightIsDepth && *result.heightIsDepth != depth;
  m_invertHeight->setVisible(senseWrong);
  m_invertHeight->setText(depth ? tr("Read height as height") : tr("Read height as depth"));
  QFrame::show();
}

void MapCheckBanner::waitForCheck() {
  m_task->waitForFinished();
  while (m_task->isRunning())
    QCoreApplication::processEvents();
}

}  // namespace relief::ui::inline panels
