// MapsPanel; see MapsPanel.h.
#include "ui/panels/MapsPanel.h"

#include "renderer/ImageConversion.h"
#include "ui/QtText.h"
#include "ui/document/MaterialDocument.h"
#include "ui/panels/MapCheckBanner.h"
#include "ui/panels/TileableBar.h"

#include <QFileInfo>
#include <QGridLayout>
#include <QLabel>
#include <QPixmap>
#include <QToolButton>
#include <QVBoxLayout>

namespace relief::ui::inline panels {
MapsPanel::MapsPanel(MaterialDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document) {
  auto* outer = new QVBoxLayout(this);
  outer->addWidget(new MapCheckBanner(document, this));
  auto* grid = new QGridLayout;
  outer->addLayout(grid);
  outer->addStretch(1);
  int row = 0;
  for (core::MapSlot slot : core::kAllMapSlots) {
    Row& widgets = m_rows[std::size_t(slot)];
    widgets.thumbnail = new QLabel;
    widgets.thumbnail->setFixedSize(kThumbnailSize, kThumbnailSize);
    widgets.thumbnail->setAlignment(Qt::AlignCenter);
    widgets.thumbnail->setFrameShape(QFrame::StyledPanel);
    widgets.description = new QLabel;
    widgets.description->setWordWrap(true);
    widgets.description->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto* load = new QToolButton;
    load->setText(tr("Load…"));
    load->setObjectName(QStringLiteral("load_") + toQString(core::mapSlotName(slot)));
    load->setToolTip(tr("Load the %1 map from a file (or drop a file on the window).")
                         .arg(toQString(core::mapSlotLabel(slot)).toLower()));
    auto* clear = new QToolButton;
    clear->setText(tr("Clear"));
    clear->setToolTip(tr("Remove the %1 map; a neutral default is used instead.")
                          .arg(toQString(core::mapSlotLabel(slot)).toLower()));
    connect(load, &QToolButton::clicked, this, [this, slot] { Q_EMIT loadRequested(slot); });
    connect(clear, &QToolButton::clicked, this, [this, slot] { m_document->clearMap(slot); });

    auto* buttons = new QVBoxLayout;
    buttons->addWidget(load);
    buttons->addWidget(clear);
    grid->addWidget(widgets.thumbnail, row, 0);
    grid->addWidget(widgets.description, row, 1);
    grid->addLayout(buttons, row, 2);
    ++row;
  }
  grid->setColumnStretch(1, 1);
  auto* orm = new QToolButton;
  orm->setText(tr("Load ORM…"));
  orm->setObjectName(QStringLiteral("load_orm"));
  orm->setToolTip(
      tr("Load one texture that packs ambient occlusion (R), roughness (G) and "
         "metallic (B), as glTF and Unreal do, into those three slots. Files named "
         "*_orm or *_arm are split so when opened or dropped."));
  connect(orm, &QToolButton::clicked, this, &MapsPanel::loadOrmRequested);
  outer->insertWidget(2, orm, 0, Qt::AlignRight);
  outer->insertWidget(3, new TileableBar(document, this));
  connect(document, &MaterialDocument::mapChanged, this, &MapsPanel::showSlot);
  connect(document, &MaterialDocument::materialReset, this, &MapsPanel::showAll);
  showAll();
}

void MapsPanel::showSlot(core::MapSlot slot) {
  const Row& row = m_rows[std::size_t(slot)];
  const core::MaterialMap& map = m_document->material().map(slot);
  const QString label = QStringLiteral("<b>%1</b>").arg(toQString(core::mapSlotLabel(slot)));
  if (!map.image) {
    row.thumbnail->setPixmap({});
    row.thumbnail->setText(tr("none"));
    row.description->setText(label + QStringLiteral("<br>") + tr("empty (neutral default)"));
    return;
  }
  row.thumbnail->setPixmap(QPixmap::fromImage(renderer::makeThumbnail(*map.image, kThumbnailSize)));
  QString name = map.sourcePath.empty()
                     ? tr("generated")
                     : QFileInfo(QString::fromStdString(map.sourcePath)).fileName();
  if (map.sourceChannel >= 0 && !map.sourcePath.empty())
    name += tr(" (channel %1)")
                .arg(QChar::fromLatin1(core::channelLetter(map.sourceChannel)).toUpper());
  row.description->setText(label + QStringLiteral("<br>") + name.toHtmlEscaped() +
                           QStringLiteral("<br>") +
                           tr("%1×%2, %3 ch")
                               .arg(map.image->width())
                               .arg(map.image->height())
                               .arg(map.image->channels()));
  row.description->setToolTip(QString::fromStdString(map.sourcePath));
}

void MapsPanel::showAll() {
  for (core::MapSlot slot : core::kAllMapSlots)
    showSlot(slot);
}

}  // namespace relief::ui::inline panels
