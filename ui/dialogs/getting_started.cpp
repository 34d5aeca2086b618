#include "ui/dialogs/getting_started.h"

#include <QDialogButtonBox>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace linkwright::ui {

GettingStartedDialog::GettingStartedDialog(QWidget* parent) : QDialog(parent), m_page(new QTextBrowser(this)) {
  setWindowTitle(tr("Getting started with Linkwright"));
  m_page->setOpenExternalLinks(true);
  const QString docs = QString::fromLatin1(kDocumentationUrl);
  m_page->setHtml(
      tr("<h2>Getting started</h2>"
         "<ol>"
         "<li><b>Open a linkage.</b> <i>Examples</i> lists linkages from textbooks and papers (the thesis "
         "crank-rocker, an engine, a shaper, six-bars, an arm); <i>File ▸ New</i> starts one of each kind.</li>"
         "<li><b>Read the answers</b> over the drawing: the Grashof class, the crank's range, the transmission "
         "angle now and over the cycle, the rocker's limits and the time ratio.</li>"
         "<li><b>Change it.</b> Drag any joint or pivot on the drawing, or type or slide its dimensions in the "
         "panel on the left. A change that cannot be assembled is refused with the reason; <i>Edit ▸ Undo</i> (Ctrl+Z) "
         "takes "
         "any change back.</li>"
         "<li><b>Move it.</b> Play and step in the Motion bar at the top, or press Space; the slider sets the "
         "crank angle. The wheel zooms the drawing, dragging the background pans it, Ctrl+0 fits it.</li>"
         "<li><b>Plot it.</b> The Kinematics tab plots each link's angle, ω and α against the crank angle or "
         "time; tick what to show, point at a curve to read a value.</li>"
         "<li><b>Forces</b> (Ctrl+F): give the links' masses in the Links table to get the driving torque and "
         "every joint's force.</li>"
         "<li><b>Design from a motion</b> in the Synthesis tab; check another tool's table with "
         "<i>File ▸ Compare…</i>; draw velocity and acceleration polygons in the Polygons tab.</li>"
         "<li><b>Share it.</b> <i>File ▸ Export</i> writes the table (CSV), images, a DXF drawing and an "
         "animation; <i>Report ▸ PDF…</i> a lab report. <i>View ▸ Presentation mode</i> (F11) is for a lecture "
         "hall.</li>"
         "</ol>"
         "<p>The documentation: <a href=\"%1\">%1</a> (forces, synthesis, compare, export, the classroom "
         "views, accuracy). <tt>linkwright-cli --help</tt> does all of this from a terminal.</p>")
          .arg(docs));
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(m_page);
  layout->addWidget(buttons);
  resize(640, 560);
}

}  // namespace linkwright::ui
