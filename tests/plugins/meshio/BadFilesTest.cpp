// SPDX-License-Identifier: MIT
// Every file of tests/data/bad does what bad/manifest.json says: rejected with a clear
// error that names the file, or loaded with the defect flagged. Nothing crashes or hangs.
#include "support/TestSupport.hpp"
#include "support/ReaderSupport.hpp"

#include <volpost/core/Quantity.hpp>

#include "host/BoundarySurface.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>

using namespace volpost;
using volpost::test::dataFile;
using volpost::test::meshioReaders;

namespace {

struct Case {
  std::string file, defect, expected;
  nlohmann::json entry;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.file; }

std::vector<Case> manifestCases() {
  std::ifstream in(dataFile("bad/manifest.json"));
  const auto manifest = nlohmann::json::parse(in);
  std::vector<Case> cases;
  for (const auto& e : manifest) {
    const std::string pattern = e.at("file");
    const std::regex glob(std::regex_replace(pattern, std::regex(R"(\*)"), ".*"));
    for (const auto& f : std::filesystem::directory_iterator(dataFile("bad"))) {
      const std::string name = f.path().filename().string();
      if (name != "manifest.json" && std::regex_match(name, glob))
        cases.push_back({name, e.at("defect"), e.at("expected"), e});
    }
  }
  std::sort(cases.begin(), cases.end(), [](const Case& a, const Case& b) { return a.file < b.file; });
  return cases;
}

const Diagnostic* diagnostic(const Model& m, const std::string& code) {
  for (const auto& d : m.diagnostics)
    if (d.code == code) return &d;
  return nullptr;
}

bool flags(const Model& m, const std::string& code, std::size_t item) {
  const Diagnostic* d = diagnostic(m, code);
  return d && std::find(d->items.begin(), d->items.end(), item) != d->items.end();
}

// What "flagged" means for each defect the manifest says to load.
const std::map<std::string, std::function<void(const Model&)>> kFlagChecks = {
    {"inverted_tets", [](const Model& m) {
       ASSERT_TRUE(diagnostic(m, "inverted-cells"));
       EXPECT_EQ(diagnostic(m, "inverted-cells")->items, (std::vector<std::size_t>{0, 1, 2, 10, 20}));
     }},
    {"inverted_hex", [](const Model& m) { EXPECT_TRUE(flags(m, "inverted-cells", 1)); }},
    {"nonplanar_face_hex", [](const Model& m) { EXPECT_TRUE(flags(m, "warped-faces", 1)); }},
    {"bowtie_face_hex", [](const Model& m) { EXPECT_TRUE(flags(m, "twisted-faces", 1)); }},
    {"zero_volume_sliver_tets", [](const Model& m) {
       EXPECT_TRUE(flags(m, "degenerate-cells", 266));
       EXPECT_TRUE(flags(m, "degenerate-cells", 267));
     }},
    {"repeated_node_tet", [](const Model& m) { EXPECT_TRUE(flags(m, "repeated-node-cells", 4)); }},
    {"duplicate_nodes_unmerged", [](const Model& m) {
       ASSERT_TRUE(diagnostic(m, "duplicate-nodes"));
       EXPECT_EQ(diagnostic(m, "duplicate-nodes")->items.size(), 1064u - 108u);
       const auto ref = meshioReaders().load(dataFile("bad/ref_small_tets.vtu"));
       EXPECT_EQ(extractBoundary(m.mesh()).boundaryFaceCount, extractBoundary(ref->mesh()).boundaryFaceCount);
     }},
    {"orphan_points", [](const Model& m) {
       ASSERT_TRUE(diagnostic(m, "unused-nodes"));
       EXPECT_EQ(diagnostic(m, "unused-nodes")->items.size(), 3u);
       const auto ref = meshioReaders().load(dataFile("bad/ref_small_tets.vtu"));
       EXPECT_EQ(m.mesh().bounds().max, ref->mesh().bounds().max);
     }},
    {"nan_in_point_data", [](const Model& m) {
       const Field* u = m.findField("U");
       ASSERT_TRUE(u);
       const ValueRange r = rangeOf(evaluate(*u, *parseQuantity("U.x", *u), 0));
       EXPECT_EQ(r.nanCount, 12u);  // every 9th of 108 nodes
       EXPECT_TRUE(std::isfinite(r.min) && std::isfinite(r.max));
     }},
    {"nan_displacements", [](const Model& m) {
       const Field* u = m.findField("U");
       ASSERT_TRUE(u);
       const ValueRange r = rangeOf(evaluate(*u, *parseQuantity("U.x", *u), 0));
       EXPECT_EQ(r.nanCount, 6u);  // the first 6 DISP records
       EXPECT_TRUE(std::isfinite(r.min) && std::isfinite(r.max));
     }},
    {"nan_coordinates", [](const Model& m) {
       ASSERT_TRUE(diagnostic(m, "nonfinite-coordinates"));
       EXPECT_TRUE(std::isfinite(m.mesh().bounds().diagonal()));
     }},
    {"field_length_mismatch", [](const Model& m) { EXPECT_TRUE(diagnostic(m, "field-dropped")); }},
    {"zero_cells", [](const Model& m) { EXPECT_EQ(m.mesh().cellCount(), 0u); }},
};

}  // namespace

class ManifestCase : public ::testing::TestWithParam<Case> {};

TEST_P(ManifestCase, DoesWhatTheManifestSays) {
  const Case& c = GetParam();
  const std::string stem = c.file.substr(0, c.file.find('.'));
  const bool reject = c.expected.rfind("reject", 0) == 0;
  std::unique_ptr<Model> model;
  std::string error;
  try {
    model = meshioReaders().load(dataFile("bad/" + c.file));
  } catch (const ReadError& e) {
    error = e.what();
  }
  SCOPED_TRACE(c.file + ": " + c.defect);
  const bool mayFlagInstead = c.expected.find("or flag") != std::string::npos ||
                              c.expected.find("or drop") != std::string::npos;
  if (reject && !(mayFlagInstead && model)) {
    ASSERT_FALSE(error.empty()) << "accepted a file that must be rejected";
    EXPECT_NE(error.find(c.file), std::string::npos) << "the message must name the file: " << error;
    if (c.entry.contains("bad_cells")) {
      EXPECT_NE(error.find("cell " + std::to_string(c.entry["bad_cells"][0].get<int>())), std::string::npos) << error;
    }
    return;
  }
  ASSERT_TRUE(model) << "rejected a file that must load: " << error;
  if (c.entry.contains("nodes")) {
    EXPECT_EQ(model->mesh().nodeCount(), c.entry["nodes"].get<std::size_t>());
  }
  if (c.entry.contains("cells")) {
    EXPECT_EQ(model->mesh().cellCount(), c.entry["cells"].get<std::size_t>());
  }
  const auto check = kFlagChecks.find(stem);
  if (c.expected.find("flag") != std::string::npos || c.expected.find("drop") != std::string::npos) {
    ASSERT_NE(check, kFlagChecks.end()) << "no check written for the flagged defect";
  }
  if (check != kFlagChecks.end()) {
    check->second(*model);
  }
  // Whatever loads must also give a boundary without crashing.
  const BoundarySurface s = extractBoundary(model->mesh());
  EXPECT_EQ(s.mesh.n_faces() > 0, model->mesh().cellCount() > 0);
}

INSTANTIATE_TEST_SUITE_P(Manifest, ManifestCase, ::testing::ValuesIn(manifestCases()), [](const auto& p) {
  std::string n = p.param.file;
  for (char& c : n) if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
});

TEST(Manifest, CoversEveryFileInTheFolder) {
  std::set<std::string> covered;
  for (const auto& c : manifestCases()) covered.insert(c.file);
  for (const auto& f : std::filesystem::directory_iterator(dataFile("bad")))
    if (f.path().filename() != "manifest.json") {
      EXPECT_TRUE(covered.count(f.path().filename().string())) << f.path();
    }
}

// Inputs the fuzzers (scripts/fuzz.sh) once broke a reader with: each must now load or be
// refused with a ReadError, and a loaded field must read or fail with a ReadError too.
TEST(FuzzRegressions, EveryKeptInputIsRefusedCleanlyOrLoads) {
  std::size_t files = 0;
  for (const auto& dir : std::filesystem::directory_iterator(dataFile("fuzz")))
    for (const auto& f : std::filesystem::directory_iterator(dir.path())) {
      SCOPED_TRACE(f.path().string());
      ++files;
      try {
        const auto model = meshioReaders().load(f.path().string());
        for (const auto& field : model->fields)
          for (std::size_t s = 0; s < field->stepCount(); ++s) {
            try {
              (void)field->values(s);
            } catch (const ReadError&) {
            }
          }
      } catch (const ReadError& e) {
        EXPECT_NE(std::string(e.what()).find(f.path().filename().string()), std::string::npos) << e.what();
      }
    }
  EXPECT_GE(files, 4u);
}
