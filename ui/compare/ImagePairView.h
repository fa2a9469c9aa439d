// ImagePairView: two pictures side by side (a generator's source and its result), each scaled
// to fit its half with its aspect ratio, with a caption above each.
#pragma once

#include <QImage>
#include <QString>
#include <QWidget>

namespace relief::ui::inline compare {

class ImagePairView : public QWidget {
  Q_OBJECT

 public:
  explicit ImagePairView(QWidget* parent = nullptr);

  void setLeft(const QImage& image, const QString& caption);
  void setRight(const QImage& image, const QString& caption);
  const QImage& right() const { return m_right; }

  QSize sizeHint() const override { return {360, 200}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  QImage m_left, m_right;
  QString m_leftCaption, m_rightCaption;
};

}  // namespace relief::ui::inline compare
