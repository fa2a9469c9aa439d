// DialogAnswerer: GUI tests' answer to a modal message box (QMessageBox::exec blocks the test's
// event loop until a button is clicked).
#pragma once

#include <QAbstractButton>
#include <QApplication>
#include <QMessageBox>
#include <QString>
#include <QTimer>

namespace relief::test {

// Answers the next message box by clicking the button with `buttonText` (or the standard
// button), recording which box it was. Polls, since the box is shown from inside exec().
class DialogAnswerer {
 public:
  explicit DialogAnswerer(QString buttonText) : m_buttonText(std::move(buttonText)) {
    QObject::connect(&m_timer, &QTimer::timeout, [this] { poll(); });
    m_timer.start(30);
  }
  int answered() const { return m_answered; }
  const QString& lastBox() const { return m_lastBox; }
  const QString& lastText() const { return m_lastText; }

 private:
  void poll() {
    auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
    if (!box)
      return;
    for (QAbstractButton* button : box->buttons()) {
      if (button->text().remove(QLatin1Char('&')) == m_buttonText) {
        m_lastBox = box->objectName();
        m_lastText = box->text();
        ++m_answered;
        button->click();
        return;
      }
    }
  }

  QString m_buttonText;
  QTimer m_timer;
  int m_answered = 0;
  QString m_lastBox;
  QString m_lastText;
};

}  // namespace relief::test
