// TileableBar; see TileableBar.h.
#include "ui/panels/TileableBar.h"

#include "core/generators/Tileable.h"
#include "core/material/MapSlot.h"
#include "ui/QtText.h"
#include "ui/document/MaterialDocument.h"
#include "ui/tasks/BackgroundTask.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

#include <memory>
#include <utility>
#include <vector>

namespace relief::ui::inline panels {
namespace {

using SlotImages = std::vector<std::pair<core::MapSlot, std::shared_ptr<const core::Image>>>;

QString axisText(const QString& axis, const core::TileAxisReport& report) {
  if (report.alreadyTiled)
    return QCoreApplication::translate("TileableBar", "%1: already tiled (seam %2×), kept")
        .arg(axis)
        .arg(report.seamBefore, 0, 'f', 2);
  return QCoreApplication::translate("TileableBar", "%1: seam %2× → %3×")
      .arg(axis)
      .arg(report.seamBefore, 0, 'f', 1)
      .arg(report.seamAfter, 0, 'f', 2);
}

}  // namespace

TileableBar::TileableBar(MaterialDocument* document, QWidget* parent)
    : QWidget(parent),
      m_document(document),
      m_task(new BackgroundTask(this)),
      m_method(new QComboBox),
      m_run(new QPushButton(tr("Make Tileable"))),
      m_progress(new QProgressBar),
      m_report(new QLabel) {
  m_method->setObjectName(QStringLiteral("tileableMethod"));
  m_method->addItem(tr("Quilt (structured)"), int(core::TileMethod::Quilt));
  m_method->addItem(tr("Cross-fade (stochastic)"), int(core::TileMethod::CrossFade));
  m_method->setToolTip(
      tr("Quilt: a patch of the map laid over each seam, cut along the least visible path; for "
         "bricks, stones, bark. Cross-fade: the map blended with itself shifted, keeping its "
         "contrast; for sand, grass, plaster."));
  m_run->setObjectName(QStringLiteral("makeTileable"));
  m_run->setToolTip(
      tr("Make every map of the material tile without a seam, with the same cut in each so "
         "they stay aligned. An axis that already tiles is kept. One undo step. Judge it with "
         "the View toolbar's Tile 3×3 and Seams (T, Shift+T)."));
  m_progress->setRange(0, 100);
  m_progress->setTextVisible(false);
  m_progress->setMaximumHeight(6);
  m_progress->hide();
  m_report->setObjectName(QStringLiteral("tileableReport"));
  m_report->setWordWrap(true);
  m_report->setTextInteractionFlags(Qt::TextSelectableByMouse);

  auto* row = new QHBoxLayout;
  row->setContentsMargins(0, 0, 0, 0);
  row->addWidget(m_method, 1);
  row->addWidget(m_run);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addLayout(row);
  layout->addWidget(m_progress);
  layout->addWidget(m_report);

  connect(m_run, &QPushButton::clicked, this, &TileableBar::makeTileable);
  connect(m_task, &BackgroundTask::progress, this,
          [this](double fraction) { m_progress->setValue(int(fraction * 100.0)); });
  connect(m_task, &BackgroundTask::finished, this, [this] {
    m_progress->hide();
    showMaps();
  });
  connect(document, &MaterialDocument::mapChanged, this, &TileableBar::showMaps);
  connect(document, &MaterialDocument::materialReset, this, [this] {
    m_report->clear();
    showMaps();
  });
  showMaps();
}

void TileableBar::showMaps() {
  bool any = false;
  for (core::MapSlot slot : core::kAllMapSlots)
    any = any || m_document->material().map(slot).image;
  m_run->setEnabled(any && !m_task->isRunning());
}

void TileableBar::makeTileable() {
  SlotImages inputs;
  for (core::MapSlot slot : core::kAllMapSlots) {
    if (const auto& image = m_document->material().map(slot).image)
      inputs.emplace_back(slot, image);
  }
  if (inputs.empty())
    return;
  core::TileableOptions options;
  options.method = core::TileMethod(m_method->currentData().toInt());
  m_run->setEnabled(false);
  m_progress->setValue(0);
  m_progress->show();
  m_report->setText(tr("Making the maps tileable…"));
  m_task->run<core::Result<core::TileableResult>>(
      [inputs, options](const core::WorkControl& control) {
        std::vector<core::TileMap> maps;
        for (const auto& [slot, image] : inputs) {
          const bool normal = slot == core::MapSlot::Normal && image->channels() >= 3;
          maps.push_back(
              {image.get(), normal ? core::TileMapRole::Normal : core::TileMapRole::Data});
        }
        return core::makeTileable(maps, options, control);
      },
      [this, inputs](core::Result<core::TileableResult>&& result) {
        if (!result) {
          m_report->setText(tr("Could not make the maps tileable: %1")
                                .arg(QString::fromStdString(result.error())));
          return;
        }
        const QString numbers = axisText(tr("Horizontal"), result->horizontal) +
                                QStringLiteral("<br>") + axisText(tr("vertical"), result->vertical);
        if (result->horizontal.alreadyTiled && result->vertical.alreadyTiled) {
          m_report->setText(tr("The maps already tile; nothing changed.<br>") + numbers);
          return;
        }
        SlotImages made;
        for (std::size_t i = 0; i < inputs.size(); ++i)
          made.emplace_back(inputs[i].first,
                            std::make_shared<const core::Image>(std::move(result->maps[i])));
        m_document->applyMaps(made, tr("Make Tileable"));
        m_report->setText(numbers);
      });
}

void TileableBar::waitForRun() {
  m_task->waitForFinished();
  while (m_task->isRunning())
    QCoreApplication::processEvents();
}

}  // namespace relief::ui::inline panels
