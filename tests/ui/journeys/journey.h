#pragma once
// A user's task through the real window (offscreen), one step at a time, as a person takes it:
// menus by their titles, keys to the focused widget, the mouse on the canvas and the side
// panel, dialogs answered as they open. After every step check() asserts what must hold
// whatever the task (the journeys' shared invariants):
// - every visible message belongs to the current design: no refusal under a panel and no
//   banner unless the step just made one (expectRefusal(), expectBanner());
// - the title names the document: its file, or what it was started from, "(not saved)";
// - the read-outs are the core's figures for the current design (the analysis strip against
//   kinematics::analyseDesign on a fresh grid sweep; the motion bar's angle against the pose);
// - no visible text shows nan or inf;
// - each toggled view draws something where the linkage supports it (instant centres);
// - nothing visible is clipped: the analysis strip's values, the motion bar, and after a fit
//   every label on the canvas inside the canvas.
// checkFitsScreen() adds what the screens people have ask (journeys/screens.json gives the
// runner a 1366×768 laptop and a 1024×768 projector): the window inside the screen, and every
// visible label, button, input and chart axis title whole and usable.

#include "ui/main_window.h"

#include <QScreen>
#include <QSize>
#include <QString>
#include <QStringList>

#include <functional>
#include <string>

namespace linkwright::test {

/// The runner's screen called `name` ("laptop" 1366×768, "projector" 1024×768); fails without it.
QScreen* journeyScreen(const QString& name);

class Journey {
public:
  /// The window at `size`, shown and settled on its default example.
  explicit Journey(QSize size = QSize(1366, 700));
  /// The window on `screen`, at the size it opens at there (not resized), shown and settled.
  explicit Journey(QScreen* screen);

  ui::MainWindow& window() { return m_window; }

  /// Triggers the action `path` names through the menu bar ("View", "Instant centres"); the
  /// '&' of mnemonics and a trailing "…" are ignored. Fails the test when it is absent or
  /// disabled.
  void menu(const QStringList& path);
  /// Examples ▸ the example `name` (the action's objectName is example_<name>).
  void example(const std::string& name);
  /// A key (with modifiers) as the keyboard gives it: to the focused widget, else the window.
  void key(int key, Qt::KeyboardModifiers modifiers = Qt::NoModifier);
  /// Types `text` into the spin box or line edit `field`, as a click there and typing, then Enter.
  void type(QWidget* field, const QString& text);
  /// Answers the next modal dialog of type `Dialog` when it opens (a file dialog, a choice),
  /// with `answer` called on it; the step that opens it follows.
  template <typename Dialog>
  void whenDialogOpens(std::function<void(Dialog*)> answer) {
    whenModalOpens([answer = std::move(answer)](QWidget* modal) {
      auto* dialog = qobject_cast<Dialog*>(modal);
      if (dialog != nullptr) answer(dialog);
      return dialog != nullptr;
    });
  }

  /// Answers the next file dialog by typing `path` into its file name field and Enter.
  void answerFileDialog(const QString& path);
  /// Accepts the next dialog of type `Dialog` as it comes (its defaults), by its OK button.
  template <typename Dialog>
  void acceptDialog() {
    whenModalOpens([](QWidget* modal) {
      auto* dialog = qobject_cast<Dialog*>(modal);
      if (dialog != nullptr) clickOk(dialog);
      return dialog != nullptr;
    });
  }

  /// The next check() allows a refusal under a panel / a banner (the step made one).
  void expectRefusal() { m_refusalExpected = true; }
  void expectBanner() { m_bannerExpected = true; }
  /// The next check() also requires every canvas label inside the canvas (the view was fitted).
  void expectFitted() { m_fitted = true; }

  /// Lets the window settle (layouts, sweeps, deferred deletes).
  void settle();
  /// The invariants above, after `step` (named in any failure).
  void check(const std::string& step);
  /// check(), and then: the window's frame inside its screen's available geometry (the whole
  /// screen in presentation mode) with a minimum size that fits there, so it can never be
  /// pushed past it; every visible QLabel and QAbstractButton as large as its text needs (or
  /// elided, "…", with the whole text in its tooltip); every visible input (spin box, combo
  /// box, line edit, slider, table) at least its minimumSizeHint; every chart's axis titles
  /// drawn whole, or their name cut short and their unit whole.
  void checkFitsScreen(const std::string& step);

private:
  static void clickOk(QWidget* dialog);
  // Calls `answer` on the active modal widget until it returns true.
  void whenModalOpens(std::function<bool(QWidget*)> answer);
  void checkMessages();
  void checkTitle();
  void checkReadouts();
  void checkNoNonFinite();
  void checkViewsDraw();
  void checkNotClipped();
  void checkInsideScreen();
  void checkWidgetsWhole();
  void checkChartsWhole();

  ui::MainWindow m_window;
  bool m_refusalExpected = false;
  bool m_bannerExpected = false;
  bool m_fitted = false;
};

/// Visible, and not clipped by any parent or the window's edge.
bool wholeInSight(const QWidget* widget);

}  // namespace linkwright::test
