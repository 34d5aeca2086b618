// The report's tables: columns sized to their widest cell, split into groups that fit the
// page (the first column, the input or the quantity, repeated in each), rows continued on the
// next page under a repeated header. Numbers are right-aligned so their points line up.

#include "kinematics/report/report_layout.h"

#include <algorithm>

namespace linkwright::kinematics::report {
namespace {

constexpr double kFontSize = 7.5;
constexpr double kRowHeight = 10.5;
constexpr double kHeaderHeight = 24.0;
constexpr double kPadding = 8.0;

std::vector<double> columnWidths(cairo_t* cr, const ReportTable& table) {
  std::vector<double> widths;
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    setFont(cr, kFontSize, true);
    double w = std::max(textWidth(cr, table.columns[c].heading), textWidth(cr, "(" + table.columns[c].unit + ")"));
    setFont(cr, kFontSize);
    for (const auto& row : table.cells) w = std::max(w, textWidth(cr, row[c]));
    widths.push_back(w + kPadding);
  }
  return widths;
}

// Groups of column indices, each starting with column 0, that fit `available` points.
std::vector<std::vector<std::size_t>> columnGroups(const std::vector<double>& widths, double available) {
  std::vector<std::vector<std::size_t>> groups{{0}};
  double used = widths.empty() ? 0.0 : widths[0];
  for (std::size_t c = 1; c < widths.size(); ++c) {
    if (used + widths[c] > available && groups.back().size() > 1) {
      groups.push_back({0});
      used = widths[0];
    }
    groups.back().push_back(c);
    used += widths[c];
  }
  return groups;
}

// Left-aligned text columns are those holding no numbers (the extremes' quantity names).
bool leftAligned(const ReportTable& table, std::size_t c) {
  return std::all_of(table.values.begin(), table.values.end(), [c](const auto& row) { return !row[c]; });
}

void header(PageCursor& page, const ReportTable& table, const std::vector<std::size_t>& group,
            const std::vector<double>& widths) {
  cairo_t* cr = page.cr();
  double x = page.left();
  for (const std::size_t c : group) {
    const auto& column = table.columns[c];
    const bool left = leftAligned(table, c);
    const auto place = [&](const std::string& text) {
      return left ? x + 2.0 : x + widths[c] - textWidth(cr, text) - 2.0;
    };
    setFont(cr, kFontSize, true);
    showText(cr, place(column.heading), page.y() + 9.0, column.heading);
    if (!column.unit.empty()) {
      setFont(cr, kFontSize);
      cairo_set_source_rgb(cr, 0.35, 0.35, 0.35);
      const std::string unit = "(" + column.unit + ")";
      showText(cr, place(unit), page.y() + 19.0, unit);
      cairo_set_source_rgb(cr, 0, 0, 0);
    }
    x += widths[c];
  }
  double total = 0.0;
  for (const std::size_t c : group) total += widths[c];
  cairo_set_line_width(cr, 0.6);
  cairo_move_to(cr, page.left(), page.y() + kHeaderHeight - 1.5);
  cairo_line_to(cr, page.left() + total, page.y() + kHeaderHeight - 1.5);
  cairo_stroke(cr);
  page.advance(kHeaderHeight);
}

void row(PageCursor& page, const ReportTable& table, std::size_t r, const std::vector<std::size_t>& group,
         const std::vector<double>& widths) {
  cairo_t* cr = page.cr();
  double total = 0.0;
  for (const std::size_t c : group) total += widths[c];
  if (r % 2 == 1) {
    cairo_set_source_rgb(cr, 0.93, 0.95, 0.98);
    cairo_rectangle(cr, page.left(), page.y(), total, kRowHeight);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
  }
  setFont(cr, kFontSize);
  double x = page.left();
  for (const std::size_t c : group) {
    const std::string& text = table.cells[r][c];
    const double at = leftAligned(table, c) ? x + 2.0 : x + widths[c] - textWidth(cr, text) - 2.0;
    showText(cr, at, page.y() + 7.8, text);
    x += widths[c];
  }
  page.advance(kRowHeight);
}

}  // namespace

void drawTable(PageCursor& page, const ReportTable& table) {
  const std::vector<double> widths = columnWidths(page.cr(), table);
  const auto groups = columnGroups(widths, page.width());
  for (std::size_t g = 0; g < groups.size(); ++g) {
    if (g > 0) page.advance(10.0);
    page.ensure(kHeaderHeight + 3.0 * kRowHeight);
    header(page, table, groups[g], widths);
    for (std::size_t r = 0; r < table.cells.size(); ++r) {
      if (kRowHeight > page.remaining()) {
        page.newPage();
        header(page, table, groups[g], widths);
      }
      row(page, table, r, groups[g], widths);
    }
  }
}

}  // namespace linkwright::kinematics::report
