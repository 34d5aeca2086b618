#include "kinematics/report/report_pdf.h"

#include "kinematics/io/safe_file.h"

#include "kinematics/report/report_layout.h"

#include <cairo-pdf.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace linkwright::kinematics::report {
namespace {

constexpr double kLinkageHeight = 330.0;
constexpr double kPlotHeight = 225.0;

void titleBlock(PageCursor& page, const ReportContent& r) {
  cairo_t* cr = page.cr();
  setFont(cr, 18.0, true);
  showText(cr, page.left(), page.y() + 18.0, r.title);
  page.advance(26.0);
  if (!r.subtitle.empty()) paragraph(page, r.subtitle, 10.0);
  cairo_set_source_rgb(cr, 0.35, 0.35, 0.35);
  paragraph(page, "Lab report by Linkwright, " + r.date, 9.0);
  cairo_set_source_rgb(cr, 0, 0, 0);
  page.advance(6.0);
}

void analysisBlock(PageCursor& page, const std::vector<InfoLine>& lines) {
  heading(page, "Analysis", 13.0 * static_cast<double>(lines.size()));
  cairo_t* cr = page.cr();
  for (const InfoLine& line : lines) {
    page.ensure(13.0);
    setFont(cr, 9.0, true);
    showText(cr, page.left(), page.y() + 9.0, line.label);
    setFont(cr, 9.0);
    showText(cr, page.left() + 118.0, page.y() + 9.0, line.text);
    page.advance(13.0);
  }
}

void tableSection(PageCursor& page, const std::string& title, const std::string& caption, const ReportTable& table) {
  heading(page, title, 80.0);
  paragraph(page, caption, 8.5);
  page.advance(4.0);
  drawTable(page, table);
}

// The whole report through `page`; the same calls count the pages and then draw them.
void layOut(PageCursor& page, const ReportContent& r) {
  titleBlock(page, r);
  drawLinkage(page, r.drawing, kLinkageHeight);
  analysisBlock(page, r.analysis);
  page.newPage();
  tableSection(page, "Kinematics", r.tableCaption, r.table);
  tableSection(page, "Extremes", r.extremesCaption, r.extremes);
  if (r.forces) tableSection(page, "Forces", r.forcesCaption, *r.forces);
  if (!r.notes.empty()) {
    heading(page, "Notes", 24.0);
    for (const std::string& note : r.notes) paragraph(page, note, 8.5);
  }
  page.newPage();
  // Four plots to a page, each at most kPlotHeight tall.
  const double plotHeight = std::min(kPlotHeight, (page.pageContentHeight() - 30.0) / 4.0);
  heading(page, "Plots", plotHeight);
  for (const ReportPlot& plot : r.plots) drawPlot(page, plot, plotHeight);
  page.finish();
}

std::pair<double, double> paperSize(Paper paper) {
  // A4 is 210 × 297 mm, Letter 8.5 × 11 in, in points.
  if (paper == Paper::Letter) return {612.0, 792.0};
  return {595.2756, 841.8898};
}

cairo_status_t discard(void*, const unsigned char*, unsigned int) { return CAIRO_STATUS_SUCCESS; }

cairo_status_t toFile(void* file, const unsigned char* data, unsigned int length) {
  return std::fwrite(data, 1, length, static_cast<std::FILE*>(file)) == length ? CAIRO_STATUS_SUCCESS
                                                                               : CAIRO_STATUS_WRITE_ERROR;
}

// Lays the report out on a surface writing through `write`; the number of pages it took.
int render(const ReportContent& r, Paper paper, cairo_write_func_t write, void* closure, int totalPages,
           cairo_status_t& status) {
  const auto [w, h] = paperSize(paper);
  cairo_surface_t* surface = cairo_pdf_surface_create_for_stream(write, closure, w, h);
  cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_TITLE, r.title.c_str());
  cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "Linkwright");
  cairo_t* cr = cairo_create(surface);
  PageCursor page(cr, w, h, r.title + ", " + r.date, totalPages);
  layOut(page, r);
  const int pages = page.page();
  status = cairo_status(cr);
  cairo_destroy(cr);
  cairo_surface_finish(surface);
  if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  return pages;
}

}  // namespace

std::optional<Paper> paperFromName(std::string_view name) {
  if (name == "a4") return Paper::A4;
  if (name == "letter") return Paper::Letter;
  return std::nullopt;
}

std::optional<Error> writeReportPdf(const ReportContent& report, Paper paper, const std::string& path) {
  cairo_status_t status = CAIRO_STATUS_SUCCESS;
  // A first pass to nowhere counts the pages, so every footer can say "page i of N".
  const int pages = render(report, paper, discard, nullptr, 0, status);
  if (status != CAIRO_STATUS_SUCCESS) return io::outputError(path, cairo_status_to_string(status));
  return io::writeFileSafely(path, [&](const std::string& to) -> std::optional<std::string> {
    errno = 0;
    std::FILE* file = std::fopen(to.c_str(), "wb");
    if (!file) return std::string(std::strerror(errno != 0 ? errno : EIO));
    render(report, paper, toFile, file, pages, status);
    const bool closed = std::fclose(file) == 0;
    if (status != CAIRO_STATUS_SUCCESS) return std::string(cairo_status_to_string(status));
    if (!closed) return std::string(std::strerror(errno != 0 ? errno : EIO));
    return std::nullopt;
  });
}

}  // namespace linkwright::kinematics::report
