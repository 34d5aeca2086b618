#pragma once
// The kinds of linkage File ▸ New offers, each started from a built-in example as its
// template, and the names the window shows for a design's kind.

#include "kinematics/design/design.h"

#include <QString>

#include <string>
#include <vector>

namespace linkwright::ui {

struct DesignTemplate {
  QString label;        ///< menu text, with its mnemonic: "&Slider-crank"
  std::string kind;     ///< the Design::kind it makes
  std::string example;  ///< the built-in example it starts from; empty: the default four-bar
};

/// File ▸ New's kinds, in menu order.
std::vector<DesignTemplate> designTemplates();

/// A new design of the template's kind.
kinematics::Design templateDesign(const DesignTemplate& kind);

/// What a design is, for people: "Four-bar", "Slider-crank", "Crank-shaper", "Watt II six-bar".
QString kindDisplayName(const kinematics::Design& design);

}  // namespace linkwright::ui
