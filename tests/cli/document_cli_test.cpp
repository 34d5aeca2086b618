// linkwright-cli on documents (FILE.json): any linkage the GUI saves analyses exactly as the
// built-in example it came from; old-version files still work; bad files fail clearly.

#include "app/cli/cli.h"
#include "tests/cli/run_cli.h"
#include "tests/support/locking_six_bar.h"

#include "kinematics/design/design.h"
#include "kinematics/io/document_json.h"
#include "kinematics/io/json.h"
#include "kinematics/model/fourbar.h"

#include "tests/support/catch.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

using namespace linkwright;

using Run = test::CliRun;
Run run(const std::vector<std::string>& args) { return test::runCliCommand(args); }

// A document in the temporary directory, removed when the test ends.
class TempDocument {
public:
  TempDocument(const std::string& name, const std::string& text)
      : m_path((std::filesystem::temp_directory_path() / ("linkwright_cli_" + name + ".json")).string()) {
    std::ofstream(m_path, std::ios::binary) << text;
  }
  ~TempDocument() { std::filesystem::remove(m_path); }
  TempDocument(const TempDocument&) = delete;
  TempDocument& operator=(const TempDocument&) = delete;
  const std::string& path() const { return m_path; }

private:
  std::string m_path;
};

}  // namespace

TEST_CASE("a saved example analyses exactly as the example", "[cli][document]") {
  for (const std::string name :
       {"thesis-crank-rocker", "miranda-fourbar", "ls3-engine", "shaper", "whitworth", "watt-i", "watt-ii",
        "stephenson-i", "stephenson-iii", "stephenson-ii", "stephenson-iii-triad"}) {
    CAPTURE(name);
    const auto design = kinematics::designForExample(name);
    REQUIRE(design.has_value());
    const TempDocument file(name, kinematics::io::writeDocument(*design));
    const Run fromFile = run({"analyze", file.path(), "--step", "5"});
    const Run fromExample = run({"analyze", "--example", name, "--step", "5"});
    INFO(fromFile.err);
    REQUIRE(fromFile.code == 0);
    REQUIRE(fromExample.code == 0);
    CHECK(fromFile.out == fromExample.out);
    CHECK(run({"extremes", file.path()}).code == 0);
    CHECK(run({"classify", file.path()}).code == 0);
  }
}

TEST_CASE("a document's speed and grid are the defaults", "[cli][document]") {
  kinematics::Design d = kinematics::designFromExample(*kinematics::findExample("watt-ii"));
  d.omega = 3.0;
  d.fromDeg = 10.0;
  d.toDeg = 40.0;
  d.samples = 4;
  const TempDocument file("grid", kinematics::io::writeDocument(d));
  const Run r = run({"analyze", file.path()});
  REQUIRE(r.code == 0);
  std::istringstream lines(r.out);
  std::string header, first;
  std::getline(lines, header);
  std::getline(lines, first);
  CHECK_THAT(first, Catch::StartsWith("10,3,0,"));           // crank angle, ω, α
  CHECK(std::count(r.out.begin(), r.out.end(), '\n') == 5);  // header + 4 rows
}

TEST_CASE("analyze and extremes note a lock between two samples", "[cli][document]") {
  // Its dyad E locks near 291.65°, between two 5° samples.
  kinematics::Design d;
  d.kind = "stephenson-iii";
  d.mechanism = *kinematics::makeSixBar(test::lockingSixBar());
  d.samples = 73;
  const TempDocument file("lock", kinematics::io::writeDocument(d));
  const Run r = run({"analyze", file.path()});
  CHECK(r.code == 0);  // every row is there
  CHECK(std::count(r.out.begin(), r.out.end(), '\n') == 74);
  // (Its four-bar is also at a change point: a toggle note for 180° comes first.)
  CHECK_THAT(r.err,
             Catch::EndsWith("\nlinkwright-cli: note: the linkage locks between crank angles 290° and 295° (a dyad "
                             "passes its assembly limit between these samples); from 295° on it is assembled "
                             "afresh on the chosen branches, so points jump there\n"));
  // extremes says so too: its figures stop at the lock.
  const Run e = run({"extremes", file.path()});
  CHECK(e.code == 0);
  CHECK_THAT(e.err, Catch::Contains("locks between crank angles 290° and 295°"));
}

TEST_CASE("classify --json escapes the document's own names", "[cli][document][json]") {
  // Point names come from the file: quotes, backslashes and control characters in them must
  // still give valid JSON that reads back to the same strings.
  kinematics::Design d = kinematics::designFromExample(*kinematics::findExample("watt-ii"));
  const std::string name = "C \"rocker\" \\ end\t1";
  d.mechanism.points[3].name = name;
  const TempDocument file("escape", kinematics::io::writeDocument(d));
  const Run r = run({"classify", file.path(), "--json"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto json = kinematics::io::parseJson(r.out);
  INFO(r.out);
  REQUIRE(json.ok());
  CHECK((*json)["transmission_angles_deg"][0]["point"] == name);
  CHECK(r.out.find('\t') == std::string::npos);
}

TEST_CASE("classify reads what a document's linkage is, not how it was stored", "[cli][document]") {
  // A four-bar saved as a general linkage classifies exactly as the four-bar.
  kinematics::Design fourBar;  // kind "linkage": nothing says it is a four-bar but its structure
  fourBar.mechanism = *kinematics::makeFourBar({60.0, 25.0, 70.0, 45.0}, kinematics::Branch::Crossed);
  const TempDocument fourBarFile("recognised_fourbar", kinematics::io::writeDocument(fourBar));
  for (const bool json : {false, true}) {
    std::vector<std::string> fromFile{"classify", fourBarFile.path()};
    std::vector<std::string> fromOptions{"classify", "--fourbar", "60,25,70,45", "--branch", "crossed"};
    if (json) fromFile.push_back("--json"), fromOptions.push_back("--json");
    const Run a = run(fromFile);
    const Run b = run(fromOptions);
    INFO(a.err);
    REQUIRE(a.code == 0);
    CHECK(a.out == b.out);
  }
  // A shaper whose kind says only "linkage" still gets its quick-return figures.
  kinematics::Design shaper = kinematics::designFromExample(*kinematics::findExample("shaper"));
  shaper.kind = "linkage";
  const TempDocument shaperFile("recognised_shaper", kinematics::io::writeDocument(shaper));
  const Run a = run({"classify", shaperFile.path()});
  const Run b = run({"classify", "--example", "shaper"});
  REQUIRE(a.code == 0);
  REQUIRE(b.code == 0);
  // The same figures after the heading line.
  CHECK(a.out.substr(a.out.find('\n')) == b.out.substr(b.out.find('\n')));
  CHECK_THAT(a.out, Catch::Contains("time ratio"));
}

TEST_CASE("a version 1 document analyses as its four-bar", "[cli][document][migration]") {
  const std::string v1 = LINKWRIGHT_TEST_DOCUMENTS "/fourbar_v1.json";
  const Run r = run({"analyze", v1, "--step", "30", "--from", "0", "--to", "60"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  const Run same =
      run({"analyze", "--fourbar", "60,25,70,45", "--branch", "crossed", "--coupler-point", "35,-20.25", "--omega",
           "1.0471975511965976", "--alpha", "0.1", "--step", "30", "--from", "0", "--to", "60"});
  CHECK(r.out == same.out);
}

TEST_CASE("a four-bar-form document and its re-saved linkage form give the same output", "[cli][document][migration]") {
  std::ifstream v1File(LINKWRIGHT_TEST_DOCUMENTS "/fourbar_v1.json");
  REQUIRE(v1File.good());
  std::stringstream v1;
  v1 << v1File.rdbuf();
  std::string v2 = v1.str();
  v2.replace(v2.find("\"version\": 1"), 12, "\"version\": 2");
  for (const auto& [version, text] : {std::pair{1, v1.str()}, std::pair{2, v2}}) {
    CAPTURE(version);
    const auto design = kinematics::io::readDocument(text);
    INFO((design.ok() ? std::string() : design.error().message));
    REQUIRE(design.ok());
    const std::string resaved = kinematics::io::writeDocument(*design);
    REQUIRE_THAT(resaved, Catch::Contains("\"type\": \"linkage\""));
    const TempDocument oldForm("fourbar_form_v" + std::to_string(version), text);
    const TempDocument linkageForm("linkage_form_v" + std::to_string(version), resaved);
    for (const std::vector<std::string>& options : {std::vector<std::string>{"analyze"},
                                                    {"analyze", "--step", "7.5", "--from", "-30", "--to", "330"},
                                                    {"analyze", "--format", "table", "--step", "30"},
                                                    {"extremes"},
                                                    {"classify"},
                                                    {"classify", "--json"}}) {
      std::vector<std::string> a = options, b = options;
      a.insert(a.begin() + 1, oldForm.path());
      b.insert(b.begin() + 1, linkageForm.path());
      CAPTURE(options);
      const Run fromOld = run(a);
      const Run fromLinkage = run(b);
      INFO(fromOld.err);
      REQUIRE(fromOld.code == 0);
      REQUIRE(fromLinkage.code == 0);
      CHECK(fromOld.out == fromLinkage.out);  // byte for byte
      CHECK(fromOld.err == fromLinkage.err);
    }
  }
}

TEST_CASE("bad documents fail with the file and the member named", "[cli][document][errors]") {
  const std::string good = kinematics::io::writeDocument(*kinematics::designForExample("watt-ii"));
  SECTION("missing file") {
    const Run r = run({"analyze", "/nonexistent/dir/x.json"});
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("/nonexistent/dir/x.json: cannot be opened for reading"));
  }
  SECTION("corrupt file") {
    const TempDocument file("corrupt", good.substr(0, good.size() / 3));
    const Run r = run({"analyze", file.path()});
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains(file.path() + ": not valid JSON"));
    CHECK(r.out.empty());
  }
  SECTION("future version") {
    std::string text = good;
    text.replace(text.find("\"version\": 2"), 12, "\"version\": 9");
    const TempDocument file("future", text);
    const Run r = run({"classify", file.path()});
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("written by a newer Linkwright"));
  }
  SECTION("a document and --example together") {
    const TempDocument file("both", good);
    const Run r = run({"analyze", file.path(), "--example", "watt-ii"});
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("--example cannot be used with a document"));
  }
  SECTION("two documents") {
    const Run r = run({"analyze", "a.json", "b.json"});
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("only one document"));
  }
  SECTION("four-bar options on a linkage") {
    const TempDocument file("branch", good);
    const Run r = run({"analyze", file.path(), "--branch", "crossed"});
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("--branch applies to four-bars"));
  }
}
