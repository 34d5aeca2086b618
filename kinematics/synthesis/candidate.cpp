#include "kinematics/synthesis/candidate.h"

namespace linkwright::kinematics {

std::string_view toString(DefectKind kind) {
  switch (kind) {
  case DefectKind::NotGrashof: return "not-grashof";
  case DefectKind::Branch: return "branch";
  case DefectKind::Order: return "order";
  case DefectKind::Transmission: return "transmission";
  case DefectKind::LinkLength: return "link-length";
  }
  return "unknown";
}

}  // namespace linkwright::kinematics
