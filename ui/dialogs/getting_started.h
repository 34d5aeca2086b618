#pragma once
// Help ▸ Getting started (F1): a first lesson in one page, from opening an example to
// exporting a report, with links to the documentation of each part.

#include <QDialog>

class QTextBrowser;

namespace linkwright::ui {

/// Where the documentation is read online (the project's docs/ folder).
inline constexpr const char* kDocumentationUrl = "https://github.com/linkwright/linkwright/tree/main/docs";

class GettingStartedDialog : public QDialog {
  Q_OBJECT
public:
  explicit GettingStartedDialog(QWidget* parent = nullptr);

  /// The page as shown (HTML), for tests.
  QTextBrowser* page() const { return m_page; }

private:
  QTextBrowser* m_page;
};

}  // namespace linkwright::ui
