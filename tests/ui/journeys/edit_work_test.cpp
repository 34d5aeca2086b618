// The work one edit does, counted in the core (kinematics/model/work_count.h): a crank length
// typed into the dimensions panel of the whole window, every view showing, recognises the
// linkage, checks the design and sweeps no more than the budget here. A view that derives again
// what the document derived shows up as a count over it.

#include "tests/ui/journeys/journey.h"

#include "ui/panels/dimensions_panel.h"

#include "kinematics/design/parameters.h"
#include "kinematics/model/work_count.h"

#include <QDoubleSpinBox>

#include "tests/support/catch.h"

using namespace linkwright;

TEST_CASE("one typed crank length recognises the four-bar, checks it and sweeps it within budget", "[journey][work]") {
  test::Journey journey;
  ui::MainWindow& window = journey.window();
  journey.check("the window on the thesis crank-rocker");
  const kinematics::WorkCount before = kinematics::workCount();
  journey.type(window.dimensionsPanel()->editor(kinematics::ParameterSlot::CrankLength), "26");
  journey.settle();
  const kinematics::WorkCount work = kinematics::workCount() - before;
  WARN("recognitions " << work.recognitions << ", design checks " << work.designChecks << ", sweeps " << work.sweeps
                       << ", swept samples " << work.sweptSamples);
  journey.check("type the crank length 26");
}
