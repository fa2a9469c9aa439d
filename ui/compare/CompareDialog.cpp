// CompareDialog; see CompareDialog.h.
#include "ui/compare/CompareDialog.h"

#include "core/compression/TextureFormat.h"
#include "ui/compare/CompareView.h"
#include "ui/panels/ParameterSlider.h"

#include <QAction>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QVBoxLayout>

namespace relief::ui::inline compare {

CompareDialog::CompareDialog(QWidget* parent) : QDialog(parent) {
  setWindowTitle(tr("Compare Compressed Map"));
  setModal(false);
  resize(900, 700);
  m_view = new CompareView(this);

  m_mode = new QComboBox(this);
  m_mode->addItem(tr("Wipe"), int(CompareView::Mode::Wipe));
  m_mode->addItem(tr("Side by side"), int(CompareView::Mode::SideBySide));
  m_mode->addItem(tr("Difference"), int(CompareView::Mode::Difference));
  m_mode->addItem(tr("Thresholded difference"), int(CompareView::Mode::Threshold));
  m_mode->addItem(tr("FLIP error"), int(CompareView::Mode::Flip));
  m_mode->addItem(tr("Block error"), int(CompareView::Mode::Blocks));
  m_mode->setToolTip(tr("1-6 switch modes"));

  m_channel = new QComboBox(this);
  m_channel->addItem(tr("All channels"), -1);
  for (const char* name : {"Red", "Green", "Blue", "Alpha"})
    m_channel->addItem(tr(name), m_channel->count() - 1);

  // The difference's gain: a slider with its value, typed or dragged (Shift: fine).
  static const core::OptionSpec gainSpec =
      core::integerOption("gain", "Gain", "times", 1, 100, 10,
                          "How many times the difference is amplified in the difference mode.");
  m_gain = new ParameterSlider(gainSpec, this);
  m_gain->setMaximumWidth(240);
  m_gain->spinBox()->setPrefix(QStringLiteral("x"));
  m_threshold = new QSpinBox(this);
  m_threshold->setRange(0, 255);
  m_threshold->setValue(8);
  m_threshold->setPrefix(tr("> "));
  m_threshold->setSuffix(tr("/255"));
  m_threshold->setToolTip(tr("Texels that differ by more than this are white"));

  auto* fit = new QPushButton(tr("Fit"), this);
  fit->setShortcut(QKeySequence(Qt::Key_F));
  auto* actual = new QPushButton(tr("1:1"), this);
  actual->setShortcut(QKeySequence(Qt::Key_1 | Qt::CTRL));
  m_zoomLabel = new QLabel(this);
  m_metrics = new QLabel(this);
  m_metrics->setTextInteractionFlags(Qt::TextSelectableByMouse);
  m_metrics->setWordWrap(true);
  m_hover = new QLabel(this);

  auto* controls = new QHBoxLayout;
  controls->addWidget(new QLabel(tr("Mode:"), this));
  controls->addWidget(m_mode);
  controls->addWidget(m_channel);
  controls->addWidget(new QLabel(tr("Gain:"), this));
  controls->addWidget(m_gain);
  controls->addWidget(new QLabel(tr("Threshold:"), this));
  controls->addWidget(m_threshold);
  controls->addStretch();
  controls->addWidget(fit);
  controls->addWidget(actual);
  controls->addWidget(m_zoomLabel);

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(controls);
  layout->addWidget(m_view, 1);
  layout->addWidget(m_hover);
  layout->addWidget(m_metrics);

  const auto updateEnabled = [this] {
    const auto mode = CompareView::Mode(m_mode->currentData().toInt());
    m_gain->setEnabled(mode == CompareView::Mode::Difference || mode == CompareView::Mode::Flip ||
                       mode == CompareView::Mode::Blocks);
    m_threshold->setEnabled(mode == CompareView::Mode::Threshold);
  };
  connect(m_mode, &QComboBox::currentIndexChanged, this, [this, updateEnabled] {
    m_view->setMode(CompareView::Mode(m_mode->currentData().toInt()));
    updateEnabled();
  });
  connect(m_channel, &QComboBox::currentIndexChanged, this, [this] {
    const int channel = m_channel->currentData().toInt();
    m_view->setChannel(channel < 0 ? std::nullopt : std::optional<int>(channel));
  });
  connect(m_gain, &ParameterSlider::valueEdited, this,
          [this](double gain) { m_view->setGain(gain); });
  connect(m_threshold, &QSpinBox::valueChanged, this,
          [this](int levels) { m_view->setThreshold(levels / 255.0); });
  connect(fit, &QPushButton::clicked, m_view, &CompareView::fitToView);
  connect(actual, &QPushButton::clicked, m_view, &CompareView::showActualPixels);
  connect(m_view, &CompareView::zoomChanged, this, [this](double zoom) {
    m_zoomLabel->setText(zoom >= 1.0 ? tr("%1:1").arg(zoom, 0, 'g', 3)
                                     : tr("1:%1").arg(1.0 / zoom, 0, 'g', 3));
  });
  connect(m_view, &CompareView::hoverText, m_hover, &QLabel::setText);
  for (int i = 0; i < m_mode->count(); ++i) {
    auto* shortcut = new QAction(this);
    shortcut->setShortcut(QKeySequence(Qt::Key_1 + i));
    connect(shortcut, &QAction::triggered, this, [this, i] { m_mode->setCurrentIndex(i); });
    addAction(shortcut);
  }
  updateEnabled();
}

QSlider* CompareDialog::gainSlider() const {
  return m_gain->slider();
}

void CompareDialog::setComparison(const QString& title, std::shared_ptr<const core::Image> original,
                                  std::shared_ptr<const core::Image> compressed,
                                  const core::CompressionReport& report) {
  setWindowTitle(tr("Compare: %1").arg(title));
  const int channels = std::min(original->channels(), compressed->channels());
  for (int i = 1; i < m_channel->count(); ++i) {
    auto* model = qobject_cast<QStandardItemModel*>(m_channel->model());
    if (model)
      model->item(i)->setEnabled(i <= channels);
  }
  if (m_channel->currentIndex() > channels)
    m_channel->setCurrentIndex(0);
  if (report.format) {
    const core::TextureFormatInfo& info = core::textureFormatInfo(*report.format);
    m_view->setBlockSize(info.blockWidth, info.blockHeight);
  }
  m_view->setImages(std::move(original), std::move(compressed));
  m_metrics->setText(QString::fromStdString(core::reportToText(report)).trimmed());
}

}  // namespace relief::ui::inline compare
