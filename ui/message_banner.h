#pragma once
// A non-modal banner across the top of the window for errors and notices (a file that would
// not open, an export that failed): it never blocks the user, and tests can read it.

#include <QFrame>

class QLabel;

namespace linkwright::ui {

class MessageBanner : public QFrame {
  Q_OBJECT
public:
  enum class Kind { Error, Information };
  explicit MessageBanner(QWidget* parent = nullptr);

  void showMessage(const QString& text, Kind kind);
  QString text() const;

private:
  QLabel* m_text;
};

}  // namespace linkwright::ui
