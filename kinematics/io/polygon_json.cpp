#include "kinematics/io/polygon_json.h"

namespace linkwright::kinematics::io {
namespace {

JsonValue vectorJson(const Eigen::Vector2d& v) { return JsonValue::array({v.x(), v.y()}); }

}  // namespace

JsonValue polygonJson(const VectorPolygon& p) {
  JsonValue j;
  j["unit"] = p.unit;
  j["box"] = {{"lower", vectorJson(p.lower)}, {"upper", vectorJson(p.upper)}};
  j["equations"] = JsonValue::array();
  for (const PolygonEquation& e : p.equations) {
    JsonValue ends = JsonValue::array();
    for (const Eigen::Vector2d& end : e.ends) ends.push_back(vectorJson(end));
    j["equations"].push_back({{"text", e.text}, {"ends", ends}, {"solver", vectorJson(e.solver)}});
  }
  j["vectors"] = JsonValue::array();
  for (const PolygonVector& v : p.vectors)
    j["vectors"].push_back({{"step", v.step},
                            {"label", v.label},
                            {"from", vectorJson(v.from)},
                            {"to", vectorJson(v.to)},
                            {"magnitude", v.value().norm()},
                            {"meaning", v.meaning}});
  j["images"] = JsonValue::array();
  for (const PolygonImage& im : p.images)
    j["images"].push_back({{"label", im.label}, {"position", vectorJson(im.position)}, {"coincident", im.coincident}});
  return j;
}

JsonValue polygonsJson(double crankAngleDeg, const DriverState& driver, const ClassroomPolygons& polygons) {
  return {{"crank_angle_deg", crankAngleDeg},
          {"omega_rad_s", driver.velocity},
          {"alpha_rad_s2", driver.acceleration},
          {"velocity", polygonJson(polygons.velocity)},
          {"acceleration", polygonJson(polygons.acceleration)}};
}

}  // namespace linkwright::kinematics::io
