#pragma once
// Internal to the report's PDF writer: a page cursor on a cairo context that starts a new page
// (with its footer) when a block does not fit, and the text helpers the sections use. Lengths
// in PostScript points (1/72 in), y down, as cairo's PDF surface has them.

#include "kinematics/report/report_content.h"

#include <cairo.h>

#include <string>

namespace linkwright::kinematics::report {

/// The page being filled and where on it.
class PageCursor {
public:
  /// `totalPages` 0 while counting the pages (the footer then says "page i").
  PageCursor(cairo_t* cr, double pageWidth, double pageHeight, std::string footer, int totalPages);

  cairo_t* cr() const { return m_cr; }
  double left() const { return kMargin; }
  double width() const { return m_pageWidth - 2.0 * kMargin; }
  double y() const { return m_y; }
  double remaining() const { return m_pageHeight - kMargin - kFooter - m_y; }
  double pageContentHeight() const { return m_pageHeight - 2.0 * kMargin - kFooter; }
  int page() const { return m_page; }

  /// Moves down by `height`.
  void advance(double height) { m_y += height; }
  /// Starts a new page unless `height` fits below the cursor.
  void ensure(double height);
  /// Ends the page (footer) and starts the next.
  void newPage();
  /// Ends the last page.
  void finish();

  static constexpr double kMargin = 48.0;
  static constexpr double kFooter = 18.0;

private:
  void footer();

  cairo_t* m_cr;
  double m_pageWidth;
  double m_pageHeight;
  std::string m_footer;
  int m_total;
  int m_page = 1;
  double m_y = kMargin;
};

/// Selects the report's sans font at `size` points, bold or not.
void setFont(cairo_t* cr, double size, bool bold = false);
/// The advance width of `text` in the current font.
double textWidth(cairo_t* cr, const std::string& text);
/// Draws `text` with its baseline starting at (x, y).
void showText(cairo_t* cr, double x, double y, const std::string& text);
/// Draws a heading and moves below it, on a new page if it and `keepWith` points below do not fit.
void heading(PageCursor& page, const std::string& text, double keepWith);
/// Draws `text` wrapped to the page width in the current font and moves below it.
void paragraph(PageCursor& page, const std::string& text, double size, bool bold = false);

/// Draws `table`, its columns split into groups that fit the page width (each group repeats
/// the first column), its rows continued on new pages under a repeated header.
void drawTable(PageCursor& page, const ReportTable& table);

/// Draws `plot` in a box `height` points tall at the cursor and moves below it.
void drawPlot(PageCursor& page, const ReportPlot& plot, double height);

/// Draws the linkage in a box at most `height` points tall at the cursor, as wide as the page
/// allows, and moves below it.
void drawLinkage(PageCursor& page, const ReportDrawing& drawing, double height);

}  // namespace linkwright::kinematics::report
