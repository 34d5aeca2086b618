// ui/plots/quality_bar.h: the box drives the document's quality both ways, and errors read as
// a mantissa and a power of ten.
#include "ui/plots/quality_bar.h"

#include <QComboBox>

#include <limits>

#include "tests/support/catch.h"

using namespace linkwright::ui;

TEST_CASE("relative errors read as a mantissa and a power of ten", "[quality_bar]") {
  CHECK(QualityBar::formatRelative(1.1e-4) == QStringLiteral("1.1 × 10⁻⁴"));
  CHECK(QualityBar::formatRelative(7.44e-5) == QStringLiteral("7.4 × 10⁻⁵"));
  CHECK(QualityBar::formatRelative(9.96e-5) == QStringLiteral("1.0 × 10⁻⁴"));  // not "10.0 × 10⁻⁵"
  CHECK(QualityBar::formatRelative(0.25) == QStringLiteral("2.5 × 10⁻¹"));
  CHECK(QualityBar::formatRelative(0.0) == QStringLiteral("< 10⁻¹⁵"));
  CHECK(QualityBar::formatRelative(std::numeric_limits<double>::quiet_NaN()) == QStringLiteral("—"));
}

TEST_CASE("the box follows the document and sets it", "[quality_bar]") {
  MechanismDocument doc;
  QualityBar bar(&doc);
  CHECK(bar.qualityBox()->currentIndex() == static_cast<int>(SamplingQuality::Normal));
  doc.setQuality(SamplingQuality::Precise);
  CHECK(bar.qualityBox()->currentIndex() == static_cast<int>(SamplingQuality::Precise));
  CHECK(bar.costText().startsWith(QStringLiteral("3600 samples/rev")));
  bar.qualityBox()->setCurrentIndex(static_cast<int>(SamplingQuality::Draft));
  CHECK(doc.quality() == SamplingQuality::Draft);
  CHECK(bar.costText().startsWith(QStringLiteral("180 samples/rev")));  // 720 px until a plot says otherwise
  doc.measureQualityNow();
  CHECK(bar.errorText().startsWith(QStringLiteral("worst peak error ")));
}
