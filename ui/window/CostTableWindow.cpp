// CostTableWindow; see CostTableWindow.h.
#include "ui/window/CostTableWindow.h"

#include "core/tracing/UvErrorMap.h"
#include "renderer/OffscreenRenderer.h"
#include "ui/document/MaterialDocument.h"
#include "ui/document/ViewDocument.h"
#include "ui/tasks/BackgroundTask.h"
#include "ui/viewport/ViewportWidget.h"
#include "ui/window/ViewportImageExport.h"

#include <QApplication>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QEventLoop>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <memory>

namespace relief::ui::inline window {
namespace {

// Timed at the viewport's size, at most this wide (the time grows with the pixels).
constexpr int kMaxWidth = 720;

enum Column { kTechnique, kFastest, kMedian, kMeanError, kP95Error, kColumns };

}  // namespace

CostTableWindow::CostTableWindow(MaterialDocument* document, ViewDocument* view,
                                 ViewportWidget* viewport, QWidget* parent)
    : QDialog(parent),
      m_document(document),
      m_view(view),
      m_viewport(viewport),
      m_task(new BackgroundTask(this)),
      m_bound(new QDoubleSpinBox),
      m_rows(new QTableWidget(0, kColumns)),
      m_status(new QLabel),
      m_apply(new QPushButton(tr("Apply"))) {
  setObjectName(QStringLiteral("costTable"));
  setWindowTitle(tr("Cost Table"));
  m_bound->setObjectName(QStringLiteral("errorBound"));
  m_bound->setRange(0.0, 100.0);
  m_bound->setDecimals(3);
  m_bound->setSingleStep(0.05);
  m_bound->setValue(core::kErrorDisplayTexels);
  m_bound->setSuffix(tr(" texels"));
  m_bound->setToolTip(
      tr("The mean UV error you accept: the cheapest technique within it is marked. A quarter "
         "texel is where parallax errors start to show as swimming."));
  m_rows->setHorizontalHeaderLabels({tr("Technique"), tr("Fastest frame (ms)"),
                                     tr("Median frame (ms)"), tr("Mean UV error"),
                                     tr("95th percentile")});
  m_rows->setEditTriggers(QAbstractItemView::NoEditTriggers);
  m_rows->setSelectionBehavior(QAbstractItemView::SelectRows);
  m_rows->setSelectionMode(QAbstractItemView::SingleSelection);
  m_rows->verticalHeader()->setVisible(false);
  m_rows->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  m_status->setWordWrap(true);
  auto* explanation = new QLabel(
      tr("Each technique at the viewport's view: the time of a frame drawn and finished (the "
         "fastest of several, the figure other work disturbs least) and the mean distance, in "
         "height-map texels, of its surface point from the exact one, over pixels where the "
         "map is not minified. Times are this machine's; the ranking is what carries over."));
  explanation->setWordWrap(true);
  auto* form = new QFormLayout;
  form->addRow(tr("Error bound (mean)"), m_bound);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
  QPushButton* measureButton = buttons->addButton(tr("Measure"), QDialogButtonBox::ActionRole);
  measureButton->setToolTip(tr("Time and measure every technique at the current view again."));
  buttons->addButton(m_apply, QDialogButtonBox::ActionRole);
  m_apply->setObjectName(QStringLiteral("applyCostRow"));
  m_apply->setToolTip(
      tr("Use the selected row's technique and samples (the marked row when "
         "none is selected): one undo step."));
  m_apply->setEnabled(false);
  connect(measureButton, &QPushButton::clicked, this, &CostTableWindow::measure);
  connect(m_apply, &QPushButton::clicked, this, &CostTableWindow::applyChoice);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
  connect(m_bound, &QDoubleSpinBox::valueChanged, this, &CostTableWindow::showTable);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(explanation);
  layout->addLayout(form);
  layout->addWidget(m_rows, 1);
  layout->addWidget(m_status);
  layout->addWidget(buttons);
}

CostTableWindow::~CostTableWindow() {
  m_task->cancel();
  m_task->waitForFinished();
}

void CostTableWindow::measure() {
  m_task->cancel();
  m_apply->setEnabled(false);
  const qreal ratio = m_viewport->devicePixelRatioF();
  const int viewportWidth = std::max(int(m_viewport->width() * ratio), 1);
  const int width = std::min(viewportWidth, kMaxWidth);
  const int height =
      std::max(int(width * double(m_viewport->height() * ratio) / double(viewportWidth)), 60);
  m_status->setText(tr("Timing every technique…"));
  QApplication::setOverrideCursor(Qt::WaitCursor);
  QApplication::processEvents();  // the status shows before the GUI thread is busy
  core::Result<renderer::CostTable> measured = [&]() -> core::Result<renderer::CostTable> {
    renderer::FrameSettings frame;
    auto offscreen = offscreenOfViewport(*m_view, *m_viewport, frame);
    if (!offscreen)
      return core::makeError(offscreen.error());
    return offscreen.value()->measureCostTableFrames(frame, width, height, {5, 0.3, 40});
  }();
  QApplication::restoreOverrideCursor();
  if (!measured) {
    m_status->setText(
        tr("Cannot measure the techniques: %1").arg(QString::fromStdString(measured.error())));
    Q_EMIT tableReady();
    return;
  }
  m_status->setText(tr("Tracing the exact intersections…"));
  auto table = std::make_shared<renderer::CostTable>(std::move(measured).value());
  m_task->run<std::shared_ptr<renderer::CostTable>>(
      [table](const core::WorkControl& control) {
        renderer::measureCostTableErrors(*table, control.cancel);
        return table;
      },
      [this, width, height](std::shared_ptr<renderer::CostTable>&& done) {
        m_table = std::move(*done);
        m_status->setText(tr("Measured at %1x%2 pixels.").arg(width).arg(height));
        showTable();
        Q_EMIT tableReady();
      });
}

void CostTableWindow::waitForTable() {
  if (!m_task->isRunning())
    return;
  QEventLoop loop;
  connect(this, &CostTableWindow::tableReady, &loop, &QEventLoop::quit);
  connect(m_task, &BackgroundTask::cancelled, &loop, &QEventLoop::quit);
  loop.exec();
}

void CostTableWindow::showTable() {
  const std::optional<std::size_t> cheapest = renderer::cheapestWithin(m_table, m_bound->value());
  m_rows->setRowCount(int(m_table.rows.size()));
  for (std::size_t i = 0; i < m_table.rows.size(); ++i) {
    const renderer::CostTableRow& row = m_table.rows[i];
    const bool marked = cheapest == i;
    const QString values[kColumns] = {
        QString::fromStdString(row.label) + (marked ? tr("  ← cheapest within the bound") : ""),
        QString::number(row.times.fastest, 'f', 1), QString::number(row.times.median, 'f', 1),
        row.pixels > 0 ? QString::number(row.meanError, 'f', 3) : tr("–"),
        row.pixels > 0 ? QString::number(row.p95Error, 'f', 3) : tr("–")};
    for (int column = 0; column < kColumns; ++column) {
      auto* item = new QTableWidgetItem(values[column]);
      QFont font = item->font();
      font.setBold(marked);
      item->setFont(font);
      if (column != kTechnique)
        item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      m_rows->setItem(int(i), column, item);
    }
  }
  // Every column shown whole: the window grows to the table's width (not past the screen).
  m_rows->setMinimumWidth(m_rows->horizontalHeader()->length() + 2 * m_rows->frameWidth() + 2);
  m_rows->setMinimumHeight(m_rows->verticalHeader()->length() +
                           m_rows->horizontalHeader()->height() + 2 * m_rows->frameWidth() + 2);
  resize(size().expandedTo(sizeHint()));
  m_apply->setEnabled(!m_table.rows.empty() && (cheapest || !m_rows->selectedItems().isEmpty()));
  if (!m_table.rows.empty() && m_table.rows.front().pixels == 0) {
    m_status->setText(
        tr("No pixel compared: the height map is minified everywhere in this "
           "view. Move closer and measure again."));
  }
}

std::optional<std::size_t> CostTableWindow::chosenRow() const {
  const QList<QTableWidgetItem*> selected = m_rows->selectedItems();
  if (!selected.isEmpty())
    return std::size_t(selected.front()->row());
  return renderer::cheapestWithin(m_table, m_bound->value());
}

void CostTableWindow::applyChoice() {
  const std::optional<std::size_t> row = chosenRow();
  if (!row || *row >= m_table.rows.size())
    return;
  // The row's technique and sample counts on the material as it is now (other edits since the
  // measurement are kept).
  const core::Material& measured = m_table.rows[*row].material;
  core::Material look = m_document->material();
  look.setTechnique(measured.technique());
  for (core::ParamId id :
       {core::ParamId::MinSamples, core::ParamId::MaxSamples, core::ParamId::SamplesPerTexel})
    look.setParameter(id, measured.parameter(id));
  m_document->applyLook(
      look,
      tr("Apply %1 from the cost table").arg(QString::fromStdString(m_table.rows[*row].label)));
}

}  // namespace relief::ui::inline window
