#include "kinematics/report/report_layout.h"

#include <algorithm>
#include <sstream>

namespace linkwright::kinematics::report {

PageCursor::PageCursor(cairo_t* cr, double pageWidth, double pageHeight, std::string footer, int totalPages)
    : m_cr(cr), m_pageWidth(pageWidth), m_pageHeight(pageHeight), m_footer(std::move(footer)), m_total(totalPages) {}

void PageCursor::ensure(double height) {
  // A block taller than a page goes on a fresh one and runs over its foot: better than looping.
  if (height > remaining() && m_y > kMargin + 1e-9) newPage();
}

void PageCursor::newPage() {
  footer();
  cairo_show_page(m_cr);
  ++m_page;
  m_y = kMargin;
}

void PageCursor::finish() {
  footer();
  cairo_show_page(m_cr);
}

void PageCursor::footer() {
  cairo_save(m_cr);
  cairo_set_source_rgb(m_cr, 0.35, 0.35, 0.35);
  setFont(m_cr, 8.0);
  const double y = m_pageHeight - kMargin + 6.0;
  cairo_set_line_width(m_cr, 0.5);
  cairo_move_to(m_cr, left(), y - 10.0);
  cairo_line_to(m_cr, left() + width(), y - 10.0);
  cairo_stroke(m_cr);
  showText(m_cr, left(), y, m_footer);
  const std::string number =
      "page " + std::to_string(m_page) + (m_total > 0 ? " of " + std::to_string(m_total) : std::string());
  showText(m_cr, left() + width() - textWidth(m_cr, number), y, number);
  cairo_restore(m_cr);
}

void setFont(cairo_t* cr, double size, bool bold) {
  // DejaVu Sans (fonts-dejavu-core, which cairo's fontconfig pulls in) has θ, ω, α, μ and ².
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

double textWidth(cairo_t* cr, const std::string& text) {
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  return extents.x_advance;
}

void showText(cairo_t* cr, double x, double y, const std::string& text) {
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, text.c_str());
}

void heading(PageCursor& page, const std::string& text, double keepWith) {
  page.ensure(24.0 + keepWith);
  if (page.y() > PageCursor::kMargin + 1e-9) page.advance(8.0);
  cairo_t* cr = page.cr();
  setFont(cr, 13.0, true);
  cairo_set_source_rgb(cr, 0.1, 0.2, 0.4);
  showText(cr, page.left(), page.y() + 13.0, text);
  cairo_set_source_rgb(cr, 0, 0, 0);
  page.advance(22.0);
}

void paragraph(PageCursor& page, const std::string& text, double size, bool bold) {
  cairo_t* cr = page.cr();
  setFont(cr, size, bold);
  const double lineHeight = size * 1.35;
  std::istringstream words(text);
  std::string word;
  std::string line;
  const auto flush = [&] {
    page.ensure(lineHeight);
    showText(cr, page.left(), page.y() + size, line);
    page.advance(lineHeight);
    line.clear();
  };
  while (words >> word) {
    const std::string candidate = line.empty() ? word : line + " " + word;
    if (!line.empty() && textWidth(cr, candidate) > page.width()) flush();
    line = line.empty() ? word : line + " " + word;
  }
  if (!line.empty()) flush();
}

}  // namespace linkwright::kinematics::report
