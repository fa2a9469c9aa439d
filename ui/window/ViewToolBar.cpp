// ViewToolBar; see ViewToolBar.h.
#include "ui/window/ViewToolBar.h"

#include "core/mesh/MeshPrimitives.h"
#include "core/view/DebugView.h"
#include "ui/QtText.h"
#include "ui/document/ViewDocument.h"
#include "ui/viewport/ViewportWidget.h"
#include "ui/window/EngineGridWindow.h"

#include <QAction>
#include <QComboBox>
#include <QFileInfo>
#include <QLabel>
#include <QSignalBlocker>

#include <algorithm>

namespace relief::ui::inline window {

ViewToolBar::ViewToolBar(ViewDocument* view, ViewportWidget* viewport, QWidget* parent)
    : QToolBar(tr("View"), parent),
      m_view(view),
      m_viewport(viewport),
      m_debugView(new QComboBox),
      m_meshBox(new QComboBox),
      m_engineBox(new QComboBox) {
  setObjectName(QStringLiteral("viewToolBar"));
  setMovable(false);

  m_debugView->setObjectName(QStringLiteral("debugView"));
  for (core::DebugView debugView : core::allDebugViews()) {
    m_debugView->addItem(toQString(core::debugViewLabel(debugView)),
                         toQString(core::debugViewName(debugView)));
  }
  m_debugView->setToolTip(
      tr("What the viewport shows: the shaded material or a diagnostic view "
         "(the CLI's --view). \"Samples per pixel\" is the cost; \"UV "
         "error\" compares every pixel with the exact intersection."));
  connect(m_debugView, &QComboBox::activated, this,
          [this](int index) { m_view->setDebugView(core::allDebugViews()[std::size_t(index)]); });
  connect(view, &ViewDocument::debugViewChanged, this, [this] {
    m_debugView->setCurrentIndex(
        m_debugView->findData(toQString(core::debugViewName(m_view->debugView()))));
  });
  addWidget(new QLabel(tr(" View ")));
  addWidget(m_debugView);

  m_meshBox->setObjectName(QStringLiteral("mesh"));
  for (core::PrimitiveShape shape : core::allPrimitiveShapes()) {
    const QString name = toQString(core::primitiveShapeName(shape));
    m_meshBox->addItem(name.left(1).toUpper() + name.mid(1));
  }
  m_meshBox->setToolTip(tr("The mesh the material is shown on (File > Open Mesh… for your own)."));
  connect(m_meshBox, &QComboBox::activated, this, [this](int index) {
    if (index < int(core::allPrimitiveShapes().size())) {
      Q_EMIT meshRequested(
          toQString(core::primitiveShapeName(core::allPrimitiveShapes()[std::size_t(index)])));
    }
  });
  addWidget(new QLabel(tr("  Mesh ")));
  addWidget(m_meshBox);
  addSeparator();

  // The tile preview: the view's, never the material's tiling (nothing exported changes).
  m_tile = addAction(tr("Tile 3×3"));
  m_tile->setObjectName(QStringLiteral("tilePreview"));
  m_tile->setCheckable(true);
  m_tile->setShortcut(QKeySequence(tr("T")));
  m_tile->setToolTip(
      tr("Repeat the material 3×3 in the view, to judge how its maps tile: seams and "
         "repetition. The material's own tiling is not changed. (T)"));
  m_seams = addAction(tr("Seams"));
  m_seams->setObjectName(QStringLiteral("tileSeams"));
  m_seams->setCheckable(true);
  m_seams->setShortcut(QKeySequence(tr("Shift+T")));
  m_seams->setToolTip(tr("Draw lines where the maps' edges meet on the surface. (Shift+T)"));
  m_hex = addAction(tr("Hex"));
  m_hex->setObjectName(QStringLiteral("hexTiling"));
  m_hex->setCheckable(true);
  m_hex->setShortcut(QKeySequence(tr("H")));
  m_hex->setToolTip(
      tr("Hex-tiling: cover the surface with hexagons that each show the maps at a random "
         "offset, blended at their borders, so a large surface shows no repetition "
         "(Mikkelsen 2022). Three map reads instead of one; not with cone, quadtree or "
         "displacement, nor in the UV error view. The material is not changed. (H)"));
  const auto applyTiles = [this] {
    m_view->setTilePreview(m_tile->isChecked() ? 3 : 1, m_seams->isChecked(), m_hex->isChecked());
  };
  connect(m_tile, &QAction::toggled, this, applyTiles);
  connect(m_seams, &QAction::toggled, this, applyTiles);
  connect(m_hex, &QAction::toggled, this, applyTiles);
  connect(view, &ViewDocument::tilePreviewChanged, this, [this] {
    const QSignalBlocker tileBlocker(m_tile), seamsBlocker(m_seams), hexBlocker(m_hex);
    m_tile->setChecked(m_view->tileRepeats() > 1);
    m_seams->setChecked(m_view->tileSeams());
    m_hex->setChecked(m_view->hexTiling());
  });
  createDistanceControls();
  addSeparator();

  // The engine preview: the relief as an engine's exported material traces it.
  m_engineBox->setObjectName(QStringLiteral("enginePreview"));
  m_engineBox->addItem(tr("Relief"));
  for (const core::EngineInfo& info : core::allEngines())
    m_engineBox->addItem(toQString(info.label), toQString(info.name));
  m_engineBox->setToolTip(
      tr("Preview the relief as an engine draws the exported material: its own tracer (step "
         "rule, refinement, depth units, LOD), fed the values the export writes, without "
         "self-shadowing (no engine material has it). Relief: this editor's technique. (E "
         "cycles)"));
  connect(m_engineBox, &QComboBox::activated, this, [this](int index) {
    m_view->setEnginePreview(index == 0 ? std::nullopt
                                        : std::optional(core::allEngines()[index - 1].engine));
  });
  connect(view, &ViewDocument::enginePreviewChanged, this, [this] {
    const std::optional<core::Engine> engine = m_view->enginePreview();
    m_engineBox->setCurrentIndex(engine ? int(*engine) + 1 : 0);
  });
  addWidget(new QLabel(tr(" Preview ")));
  addWidget(m_engineBox);
  // In the View menu (MainWindow), not on the bar: the box shows the state.
  m_engineCycle = new QAction(tr("Next Engine Preview"), this);
  m_engineCycle->setObjectName(QStringLiteral("nextEnginePreview"));
  m_engineCycle->setShortcut(QKeySequence(tr("E")));
  connect(m_engineCycle, &QAction::triggered, this, [this] {
    const int next = (m_engineBox->currentIndex() + 1) % m_engineBox->count();
    m_view->setEnginePreview(next == 0 ? std::nullopt
                                       : std::optional(core::allEngines()[next - 1].engine));
  });
  m_engineGrid = addAction(tr("Engine Grid…"));
  m_engineGrid->setObjectName(QStringLiteral("engineGridAction"));
  m_engineGrid->setShortcut(QKeySequence(tr("Shift+E")));
  m_engineGrid->setToolTip(
      tr("Relief's exact trace and every engine side by side at this view, each with its UV "
         "error against the exact trace. (Shift+E)"));
  connect(m_engineGrid, &QAction::triggered, this, [this] {
    if (!m_engineGridWindow)
      m_engineGridWindow = new EngineGridWindow(m_view, m_viewport, parentWidget());
    m_engineGridWindow->show();
    m_engineGridWindow->raise();
    m_engineGridWindow->refresh();
  });
  addSeparator();

  m_compare = addAction(tr("Compare A|B"));
  m_compare->setObjectName(QStringLiteral("compare"));
  m_compare->setCheckable(true);
  m_compare->setShortcut(QKeySequence(tr("C")));
  m_compare->setToolTip(
      tr("Split the viewport: the live material left (A), a held copy right "
         "(B), on the same camera. Drag the divider. (C)"));
  connect(m_compare, &QAction::toggled, m_viewport, &ViewportWidget::setComparing);
  QAction* hold = m_holdAsB = addAction(tr("Hold as B"));
  hold->setShortcut(QKeySequence(tr("Shift+C")));
  hold->setToolTip(
      tr("Copy the current material to the B side, then change A to compare "
         "(e.g. POM against parallax-limited, or 64 samples against 16). "
         "(Shift+C)"));
  connect(hold, &QAction::triggered, this, [this] {
    m_viewport->holdCurrentAsComparison();
    m_compare->setChecked(true);
  });
  connect(view, &ViewDocument::meshChanged, this, [this] { showMeshSource(m_view->meshSource()); });
}

// The view distance: powers of two, as mip levels halve; ] and [ step through them (View menu).
void ViewToolBar::createDistanceControls() {
  m_distanceBox = new QComboBox;
  m_distanceBox->setObjectName(QStringLiteral("viewDistance"));
  for (int distance = 1; distance <= ViewDocument::kMaxViewDistance; distance *= 2)
    m_distanceBox->addItem(tr("×%1").arg(distance), distance);
  m_distanceBox->setToolTip(
      tr("Look at the material as from this many times farther: it repeats that many times "
         "more, so each texel covers fewer pixels and the viewport samples the mip levels an "
         "engine samples there, from the chain the Compress panel writes (its Mipmaps and Mip "
         "filter), original or compressed. The Mip level view shows which. ([ and ])"));
  connect(m_distanceBox, &QComboBox::activated, this,
          [this](int index) { m_view->setViewDistance(m_distanceBox->itemData(index).toInt()); });
  connect(m_view, &ViewDocument::tilePreviewChanged, this, [this] {
    m_distanceBox->setCurrentIndex(m_distanceBox->findData(m_view->viewDistance()));
  });
  addWidget(new QLabel(tr(" Distance ")));
  addWidget(m_distanceBox);
  const auto step = [this](int by) {
    const int index = std::clamp(m_distanceBox->currentIndex() + by, 0, m_distanceBox->count() - 1);
    m_view->setViewDistance(m_distanceBox->itemData(index).toInt());
  };
  m_farther = new QAction(tr("Look From Farther"), this);
  m_farther->setObjectName(QStringLiteral("fartherAction"));
  m_farther->setShortcut(QKeySequence(tr("]")));
  connect(m_farther, &QAction::triggered, this, [step] { step(1); });
  m_closer = new QAction(tr("Look From Closer"), this);
  m_closer->setObjectName(QStringLiteral("closerAction"));
  m_closer->setShortcut(QKeySequence(tr("[")));
  connect(m_closer, &QAction::triggered, this, [step] { step(-1); });
}

// The toolbar's mesh box follows the view document: a primitive's entry, or the file's name
// last.
void ViewToolBar::showMeshSource(const QString& source) {
  const int customIndex = int(core::allPrimitiveShapes().size());
  if (const auto shape = core::findPrimitiveShape(source.toStdString())) {
    m_meshBox->setCurrentIndex(int(*shape));
    return;
  }
  if (m_meshBox->count() > customIndex)
    m_meshBox->removeItem(customIndex);
  m_meshBox->addItem(QFileInfo(source).fileName());
  m_meshBox->setCurrentIndex(customIndex);
}

}  // namespace relief::ui::inline window
