#include "kinematics/io/dxf_export.h"

#include "kinematics/io/safe_file.h"

#include <dl_dxf.h>
#include <dl_writer_ascii.h>

#include <charconv>
#include <cstdio>
#include <string>
#include <utility>

namespace linkwright::kinematics::io {
namespace {

// dxflib prints reals with "%.16f": within 5e-17, but with fewer than 17 significant digits
// below 1 (1.2345678901234567e-5 keeps 12). This writer prints the shortest fixed-point text
// that reads back as the same double (std::to_chars: whatever the value and the locale), with
// a decimal point always; the rest of the file is dxflib's.
// dxflib's writer into memory, in DL_WriterA's layout (each group code right-aligned in three
// columns on its own line, then its value), so that safe_file.h writes the file and checks
// every write: DL_WriterA's stream reported no error when its last buffer failed to reach a
// full disk. Reals in fixed point with all their digits (a DXF reader takes them so), not
// DL_WriterA's %.16lf-or-shorter, so that a drawing reads back to the last bit.
// DL_Dxf takes a DL_WriterA: its own stream is opened on /dev/null and never written.
class MemoryWriter : public DL_WriterA {
public:
  MemoryWriter(std::string& out, DL_Codes::version dxfVersion) : DL_WriterA("/dev/null", dxfVersion), m_out(out) {}
  void dxfReal(int gc, double value) const override {
    char text[400];  // the longest fixed-point double, 1.8e308, has 309 digits
    const auto [end, ec] = std::to_chars(text, text + sizeof text, value, std::chars_format::fixed);
    std::string out(text, ec == std::errc{} ? end : text);
    if (out.find('.') == std::string::npos) out += ".0";
    dxfString(gc, out);
  }
  void dxfInt(int gc, int value) const override { dxfString(gc, std::to_string(value)); }
  void dxfHex(int gc, int value) const override {
    char text[16];
    std::snprintf(text, sizeof text, "%0X", static_cast<unsigned>(value));
    dxfString(gc, text);
  }
  void dxfString(int gc, const char* value) const override { dxfString(gc, std::string(value)); }
  void dxfString(int gc, const std::string& value) const override {
    m_out += gc < 10 ? "  " : gc < 100 ? " " : "";
    m_out += std::to_string(gc);
    m_out += '\n';
    m_out += value;
    m_out += '\n';
  }

private:
  std::string& m_out;
};

// Layer colours (AutoCAD colour index): GROUND white, the parts cycling red, yellow, green,
// cyan, blue, magenta so neighbours differ.
int layerColour(std::size_t index) { return index == 0 ? 7 : 1 + static_cast<int>((index - 1) % 6); }

// Lineweights (group 370): entities take their layer's (−1), layers the viewer's default (−3).
DL_Attributes onLayer(const std::string& layer) { return DL_Attributes(layer, 256, -1, "BYLAYER", 1.0); }

// The HEADER and TABLES sections: dxflib's minimal R2000 set (the order its manual gives),
// with $INSUNITS and one LAYER entry per part.
void writeTables(DL_Dxf& dxf, DL_WriterA& dw, const LinkDrawing& drawing) {
  dxf.writeHeader(dw);
  dw.dxfString(9, "$INSUNITS");
  dw.dxfInt(70, dxfInsUnits(drawing.lengthUnit));
  dw.sectionEnd();
  dw.sectionTables();
  dxf.writeVPort(dw);
  dw.tableLinetypes(3);
  dxf.writeLinetype(dw, DL_LinetypeData("BYBLOCK", "", 0, 0, 0.0));
  dxf.writeLinetype(dw, DL_LinetypeData("BYLAYER", "", 0, 0, 0.0));
  dxf.writeLinetype(dw, DL_LinetypeData("CONTINUOUS", "Continuous", 0, 0, 0.0));
  dw.tableEnd();
  dw.tableLayers(static_cast<int>(drawing.layers.size()) + 1);
  dxf.writeLayer(dw, DL_LayerData("0", 0), DL_Attributes("", 7, -3, "CONTINUOUS", 1.0));
  for (std::size_t i = 0; i < drawing.layers.size(); ++i)
    dxf.writeLayer(dw, DL_LayerData(drawing.layers[i].name, 0),
                   DL_Attributes("", layerColour(i), -3, "CONTINUOUS", 1.0));
  dw.tableEnd();
  dw.tableStyle(1);
  dxf.writeStyle(dw, DL_StyleData("Standard", 0, 0.0, 1.0, 0.0, 0, 2.5, "txt", ""));
  dw.tableEnd();
  dxf.writeView(dw);
  dxf.writeUcs(dw);
  dw.tableAppid(1);
  dxf.writeAppid(dw, "ACAD");
  dw.tableEnd();
  dxf.writeDimStyle(dw, 1, 1, 1, 1, 1);
  dxf.writeBlockRecord(dw);
  dw.tableEnd();
  dw.sectionEnd();
  dw.sectionBlocks();
  for (const char* block : {"*Model_Space", "*Paper_Space", "*Paper_Space0"}) {
    dxf.writeBlock(dw, DL_BlockData(block, 0, 0.0, 0.0, 0.0));
    dxf.writeEndBlock(dw, block);
  }
  dw.sectionEnd();
}

void writeLayer(DL_Dxf& dxf, DL_WriterA& dw, const DrawingLayer& layer) {
  const DL_Attributes attributes = onLayer(layer.name);
  for (const Outline& outline : layer.outlines) {
    dxf.writePolyline(dw, DL_PolylineData(static_cast<int>(outline.size()), 0, 0, 1), attributes);
    for (const OutlineVertex& v : outline) dxf.writeVertex(dw, DL_VertexData(v.point.x(), v.point.y(), 0.0, v.bulge));
    dxf.writePolylineEnd(dw);
  }
  for (const Hole& h : layer.holes)
    dxf.writeCircle(dw, DL_CircleData(h.centre.x(), h.centre.y(), 0.0, h.diameter / 2.0), attributes);
  for (const DrawingLine& l : layer.lines)
    dxf.writeLine(dw, DL_LineData(l.from.x(), l.from.y(), 0.0, l.to.x(), l.to.y(), 0.0), attributes);
}

// The whole drawing as DXF text.
std::string dxfText(const LinkDrawing& drawing) {
  std::string text;
  DL_Dxf dxf;  // writes R2000 (AC1015), the version of the writer below
  MemoryWriter dw(text, DL_Codes::AC1015);
  writeTables(dxf, dw, drawing);
  dw.sectionEntities();
  for (const DrawingLayer& layer : drawing.layers) writeLayer(dxf, dw, layer);
  dw.sectionEnd();
  dxf.writeObjects(dw);
  dxf.writeObjectsEnd(dw);
  dw.dxfEOF();
  return text;
}

}  // namespace

int dxfInsUnits(const std::string& unit) {
  static const std::pair<const char*, int> kCodes[] = {{"in", 1},  {"ft", 2},  {"mi", 3}, {"mm", 4},
                                                       {"cm", 5},  {"m", 6},   {"km", 7}, {"yd", 10},
                                                       {"nm", 12}, {"um", 13}, {"dm", 14}};
  for (const auto& [name, code] : kCodes)
    if (unit == name) return code;
  return 0;
}

std::optional<Error> writeDxf(const LinkDrawing& drawing, const std::string& path) {
  return writeFileSafely(path, dxfText(drawing));
}

std::optional<Error> exportLinkDrawingDxf(const Mechanism& mechanism, const Pose& pose, const DrawingOptions& options,
                                          const std::string& path) {
  const auto drawing = linkDrawing(mechanism, pose, options);
  if (!drawing) return drawing.error();
  return writeDxf(*drawing, path);
}

}  // namespace linkwright::kinematics::io
