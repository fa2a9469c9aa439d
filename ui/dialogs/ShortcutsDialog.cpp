// ShortcutsDialog; see ShortcutsDialog.h.
#include "ui/dialogs/ShortcutsDialog.h"

#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace relief::ui::inline dialogs {
namespace {

QString plainText(QString text) {
  return text.remove(QLatin1Char('&')).remove(QStringLiteral("…"));
}

void addMenu(QTreeWidget* tree, QTreeWidgetItem* parent, const QMenu* menu) {
  for (QAction* action : menu->actions()) {
    if (action->menu()) {
      addMenu(tree, parent, action->menu());
      continue;
    }
    if (action->shortcuts().isEmpty())
      continue;
    QStringList keys;
    for (const QKeySequence& key : action->shortcuts())
      keys << key.toString(QKeySequence::NativeText);
    new QTreeWidgetItem(parent, {plainText(action->text()), keys.join(QStringLiteral(", "))});
  }
}

}  // namespace

ShortcutsDialog::ShortcutsDialog(const QMenuBar* menuBar, const QString& viewportControls,
                                 QWidget* parent)
    : QDialog(parent) {
  setWindowTitle(tr("Keyboard shortcuts"));
  auto* tree = new QTreeWidget;
  tree->setObjectName(QStringLiteral("shortcutList"));
  tree->setColumnCount(2);
  tree->setHeaderLabels({tr("Action"), tr("Shortcut")});
  tree->setRootIsDecorated(false);
  for (QAction* top : menuBar->actions()) {
    if (!top->menu())
      continue;
    auto* group = new QTreeWidgetItem(tree, {plainText(top->text())});
    QFont bold = group->font(0);
    bold.setBold(true);
    group->setFont(0, bold);
    addMenu(tree, group, top->menu());
    if (group->childCount() == 0)
      delete group;
  }
  tree->expandAll();
  tree->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
  auto* controls = new QLabel(viewportControls);
  controls->setWordWrap(true);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(tree, 1);
  layout->addWidget(new QLabel(tr("<b>Viewport</b>")));
  layout->addWidget(controls);
  layout->addWidget(buttons);
  resize(520, 640);
}

}  // namespace relief::ui::inline dialogs
