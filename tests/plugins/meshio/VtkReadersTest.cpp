// SPDX-License-Identifier: MIT
#include "support/TestSupport.hpp"
#include "support/ReaderSupport.hpp"

#include <volpost/core/Quantity.hpp>

#include <glm/geometric.hpp>

#include <cmath>

using namespace volpost;
using volpost::test::dataFile;
using volpost::test::meshioReaders;

namespace {

const char* kBarEncodings[] = {"bar/bar_tet4.vtu", "bar/bar_tet4_ascii.vtu", "bar/bar_tet4_binary.vtu",
                               "bar/bar_tet4.vtk", "bar/bar_tet4_ascii.vtk"};

}  // namespace

class BarInEveryEncoding : public ::testing::TestWithParam<const char*> {};

TEST_P(BarInEveryEncoding, HasTheMeshAndFieldsOfTheSolverRun) {
  const auto model = meshioReaders().load(dataFile(GetParam()));
  EXPECT_EQ(model->mesh().nodeCount(), 3091u);
  EXPECT_EQ(model->mesh().cellCount(), 12431u);
  EXPECT_EQ(model->mesh().countsByType().at(CellType::Tet4), 12431u);
  const Bounds b = model->mesh().bounds();
  EXPECT_EQ(b.min, glm::dvec3(0.0));
  EXPECT_EQ(b.max, glm::dvec3(10.0, 1.0, 1.0));
  for (const char* name : {"U", "S", "S_Mises", "S11", "region"}) EXPECT_TRUE(model->findField(name)) << name;
  EXPECT_EQ(model->findField("S")->kind(), FieldKind::SymTensor);
  EXPECT_EQ(model->findField("region")->location(), FieldLocation::Cell);
  EXPECT_TRUE(model->diagnostics.empty());
}

TEST_P(BarInEveryEncoding, AgreesWithTheAppendedBinaryFile) {
  static const auto reference = meshioReaders().load(dataFile("bar/bar_tet4.vtu"));
  const auto model = meshioReaders().load(dataFile(GetParam()));
  // ASCII legacy files carry about 11 significant digits.
  for (std::size_t i = 0; i < model->mesh().nodeCount(); i += 7)
    EXPECT_NEAR(glm::length(model->mesh().nodes[i] - reference->mesh().nodes[i]), 0.0, 1e-9);
  for (const char* name : {"U", "S"}) {
    const auto& a = model->findField(name)->values(0);
    const auto& r = reference->findField(name)->values(0);
    ASSERT_EQ(a.size(), r.size());
    for (std::size_t i = 0; i < a.size(); ++i) ASSERT_NEAR(a[i], r[i], 1e-9 * (1.0 + std::abs(r[i]))) << name << " " << i;
  }
}

TEST_P(BarInEveryEncoding, AxialStressIsForceOverAreaAwayFromTheClamp) {
  // The bar is pulled with a traction of 100 MPa: S11 = F/A = 100 for 3 < x < 7.
  const auto model = meshioReaders().load(dataFile(GetParam()));
  const Field& s = *model->findField("S");
  const auto sxx = evaluate(s, *parseQuantity("S.xx", s), 0);
  const auto mises = evaluate(s, *parseQuantity("S.mises", s), 0);
  const auto& written = model->findField("S_Mises")->values(0);
  std::size_t checked = 0;
  for (std::size_t n = 0; n < model->mesh().nodeCount(); ++n) {
    EXPECT_NEAR(mises[n], written[n], 1e-3 * written[n]);  // ccx prints 6 digits
    const double x = model->mesh().nodes[n].x;
    if (x > 3.0 && x < 7.0) {
      EXPECT_NEAR(sxx[n], 100.0, 0.01) << "node " << n;
      ++checked;
    }
  }
  EXPECT_GT(checked, 500u);
}

INSTANTIATE_TEST_SUITE_P(Files, BarInEveryEncoding, ::testing::ValuesIn(kBarEncodings),
                         [](const auto& p) {
                           std::string n = std::filesystem::path(p.param).filename().string();
                           for (char& c : n) if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

TEST(VtuReader, BinaryFieldsAreDecodedOnlyWhenFirstUsed) {
  const auto model = meshioReaders().load(dataFile("bar/bar_tet4.vtu"));
  const Field* s = model->findField("S");
  EXPECT_FALSE(s->isLoaded(0));
  EXPECT_EQ(s->values(0).size(), 3091u * 6u);
  EXPECT_TRUE(s->isLoaded(0));
}

TEST(VtuReader, ReportsProgressAndCanBeCancelled) {
  double last = -1.0;
  bool monotonic = true;
  Progress watch([&](double f, const std::string&) {
    monotonic = monotonic && f >= last;
    last = f;
    return true;
  });
  meshioReaders().load(dataFile("bar/bar_tet4.vtu"), watch);
  EXPECT_TRUE(monotonic);
  EXPECT_DOUBLE_EQ(last, 1.0);
  Progress cancel([](double f, const std::string&) { return f < 0.3; });
  EXPECT_THROW(meshioReaders().load(dataFile("bar/bar_tet4.vtu"), cancel), Cancelled);
}

TEST(ReaderRegistry, ChoosesByContentWhenTheExtensionLies) {
  const auto tmp = std::filesystem::temp_directory_path() / "volpost_mislabeled.vtk";
  std::filesystem::copy_file(dataFile("bar/bar_tet4.vtu"), tmp, std::filesystem::copy_options::overwrite_existing);
  const auto model = meshioReaders().load(tmp.string());
  EXPECT_EQ(model->formatName, "VTK XML unstructured grid");
  EXPECT_EQ(model->mesh().cellCount(), 12431u);
  std::filesystem::remove(tmp);
}

TEST(ReaderRegistry, ExplainsWhatAnUnreadableFileLooksLike) {
  const auto expectMessage = [](const std::string& file, const std::string& words) {
    try {
      meshioReaders().load(dataFile(file));
      ADD_FAILURE() << file << " was accepted";
    } catch (const ReadError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(file.substr(file.find('/') + 1)), std::string::npos) << e.what();
    }
  };
  expectMessage("bad/binary_garbage.vtk", "binary data");
  expectMessage("bad/gzipped_named.msh", "gzip");
  expectMessage("bad/binary_png_named.frd", "PNG");
  expectMessage("bad/empty.vtu", "empty");
  EXPECT_THROW(meshioReaders().load(dataFile("bad/no_such_file.vtu")), ReadError);
  EXPECT_THROW(meshioReaders().load(dataFile("bad")), ReadError);
}

TEST(LargerCases, WheelAndBracketLoadWithAllCellTypes) {
  VOLPOST_SHARED_OR_SKIP(wheel, "wheel/mixed/wheel_mixed.vtu");
  const auto model = meshioReaders().load(wheel);
  const auto counts = model->mesh().countsByType();
  for (CellType t : {CellType::Hex8, CellType::Wedge6, CellType::Tet4, CellType::Pyramid5})
    EXPECT_GT(counts.count(t) ? counts.at(t) : 0u, 0u) << cellTypeName(t);
  for (const auto& d : model->diagnostics) EXPECT_NE(d.code, "inverted-cells") << d.message;
  VOLPOST_SHARED_OR_SKIP(bracket, "bracket/tet10/bracket_tet10.vtk");
  const auto b = meshioReaders().load(bracket);
  EXPECT_GT(b->mesh().countsByType().at(CellType::Tet10), 0u);
  for (const auto& d : b->diagnostics) EXPECT_NE(d.code, "inverted-cells") << d.message;
}
