#include "kinematics/io/csv_writer.h"

#include "kinematics/io/number_format.h"
#include "kinematics/model/units.h"

#include <cmath>

namespace linkwright::kinematics::io {
namespace {

constexpr const char* kLineEnd = "\r\n";

bool isDrivenCrank(const Mechanism& m, const Link& link) {
  const auto* crank = std::get_if<CrankPoint>(&m.points[link.second.index].definition);
  return crank != nullptr && crank->pivot == link.first && crank->phase == 0.0;
}

bool isMoving(const Point& p) { return !std::holds_alternative<GroundPoint>(p.definition); }
bool isDyad(const Point& p) { return std::holds_alternative<RrrPoint>(p.definition); }

std::size_t dyadCount(const Mechanism& m) {
  std::size_t n = 0;
  for (const Point& p : m.points) n += isDyad(p) ? 1 : 0;
  return n;
}

// The input column is the requested grid: 12 significant digits print 30 as "30", not as the
// radian round trip "29.999999999999996".
std::string inputAngleText(double angle) { return formatShort(radToDeg(angle), 12); }

} // namespace

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

std::vector<std::string> sweepCsvHeader(const Mechanism& m, const SolveRequest& request) {
  const bool vel = request.velocities || request.accelerations;
  const bool acc = request.accelerations;
  std::vector<std::string> h{"crank_angle_deg"};
  for (const Link& link : m.links) {
    if (!isDrivenCrank(m, link)) h.push_back(link.name + "_angle_deg");
    if (vel) h.push_back(link.name + "_omega_rad_s");
    if (acc) h.push_back(link.name + "_alpha_rad_s2");
  }
  const bool severalDyads = dyadCount(m) > 1;
  for (const Point& p : m.points)
    if (isDyad(p)) h.push_back(severalDyads ? "transmission_angle_" + p.name + "_deg" : "transmission_angle_deg");
  const std::string& u = m.lengthUnit;
  for (const Point& p : m.points) {
    if (!isMoving(p)) continue;
    h.push_back(p.name + "_x_" + u);
    h.push_back(p.name + "_y_" + u);
    if (vel) {
      h.push_back(p.name + "_vx_" + u + "_s");
      h.push_back(p.name + "_vy_" + u + "_s");
    }
    if (acc) {
      h.push_back(p.name + "_ax_" + u + "_s2");
      h.push_back(p.name + "_ay_" + u + "_s2");
    }
  }
  return h;
}

void writeSweepCsv(std::ostream& out, const Mechanism& m, const SweepResult& r) {
  const std::vector<std::string> header = sweepCsvHeader(m, r.request);
  for (std::size_t c = 0; c < header.size(); ++c) out << (c ? "," : "") << csvField(header[c]);
  out << kLineEnd;
  const bool vel = !r.linkOmega.empty();
  const bool acc = !r.linkAlpha.empty();
  std::string row;
  for (std::size_t j = 0; j < r.size(); ++j) {
    if (!r.assembled(j)) continue;
    const bool rates = r.ok(j);  // at a toggle the rates do not exist: empty cells
    auto cell = [&](double value, bool present = true) {
      row += ',';
      if (present) row += formatDouble(value);
    };
    row = inputAngleText(r.inputAngle[j]);
    for (std::size_t k = 0; k < m.links.size(); ++k) {
      if (!isDrivenCrank(m, m.links[k])) cell(radToDeg(r.linkAngle[k][j]));
      if (vel) cell(r.linkOmega[k][j], rates);
      if (acc) cell(r.linkAlpha[k][j], rates);
    }
    for (std::size_t i = 0; i < m.points.size(); ++i)
      if (isDyad(m.points[i])) cell(radToDeg(r.transmissionAngle[i][j]));
    for (std::size_t i = 0; i < m.points.size(); ++i) {
      if (!isMoving(m.points[i])) continue;
      cell(r.position[i][j].x());
      cell(r.position[i][j].y());
      if (vel) {
        cell(r.velocity[i][j].x(), rates);
        cell(r.velocity[i][j].y(), rates);
      }
      if (acc) {
        cell(r.acceleration[i][j].x(), rates);
        cell(r.acceleration[i][j].y(), rates);
      }
    }
    out << row << kLineEnd;
  }
}

} // namespace linkwright::kinematics::io
