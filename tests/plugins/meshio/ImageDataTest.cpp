// SPDX-License-Identifier: MIT
// VTK XML image data (.vti) as written by VTK itself in three encodings: the grid (extent
// not starting at 0, spacing, a rotated Direction), point and cell arrays at the right
// points, and refusals of damaged files that name the line.
#include "VtiReader.hpp"
#include "VtkLegacyReader.hpp"
#include "VtuReader.hpp"

#include "support/TestSupport.hpp"

#include <volpost/core/Error.hpp>

#include <glm/geometric.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>

namespace volpost::meshio {
namespace {

std::string text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class ImageData : public ::testing::TestWithParam<const char*> {};

TEST_P(ImageData, ReadsTheGridAndItsArraysAsVtkWroteThem) {
  const auto model = VtiReader().read(test::dataFile(std::string("formats/") + GetParam()), {});
  ASSERT_TRUE(model->grid);
  const RegularGrid& g = *model->grid;
  EXPECT_EQ(g.dims, (std::array<std::size_t, 3>{5, 4, 3}));
  EXPECT_EQ(g.firstLabel, (std::array<double, 3>{1, 0, 2}));
  // VTK's TransformIndexToPhysicalPoint(3, 2, 3):
  const glm::dvec3 vtkPoint(11.28524463035774, -1.0790514454451876, 6.5);
  EXPECT_LT(glm::distance(g.position(3 - 1, 2 - 0, 3 - 2), vtkPoint), 1e-12);
  EXPECT_EQ(model->mesh().nodeCount(), 60u);
  EXPECT_EQ(model->mesh().cellCount(), 24u);
  const Field* temperature = model->findField("temperature");
  const Field* velocity = model->findField("velocity");
  const Field* material = model->findField("material");
  ASSERT_TRUE(temperature && velocity && material);
  EXPECT_EQ(material->location(), FieldLocation::Cell);
  EXPECT_EQ(velocity->components(), 3);
  for (std::size_t k = 0; k < 3; ++k)
    for (std::size_t j = 0; j < 4; ++j)
      for (std::size_t i = 0; i < 5; ++i) {
        const std::size_t p = g.pointIndex(i, j, k);
        EXPECT_EQ(temperature->values(0)[p], 100.0 + double(i + 1) + 10.0 * double(j) + 100.0 * double(k + 2));
        EXPECT_EQ(velocity->values(0)[3 * p + 2], double(k + 2));
      }
  for (std::size_t c = 0; c < 24; ++c) EXPECT_EQ(material->values(0)[c], double(c % 3));
  // Kept in the types VTK wrote: 64-bit floats, 32-bit floats, 32-bit integers.
  EXPECT_EQ(temperature->samples(0).type(), SampleType::Float64);
  EXPECT_EQ(velocity->samples(0).type(), SampleType::Float32);
  EXPECT_EQ(material->samples(0).type(), SampleType::Int32);
  // Every hexahedron is right-handed (the model checks would flag inverted ones).
  for (std::size_t c = 0; c < model->mesh().cellCount(); ++c) EXPECT_GT(signedCellVolume(model->mesh(), c), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Encodings, ImageData,
                         ::testing::Values("image_ascii.vti", "image_binary.vti", "image_appended_zlib.vti"));

TEST(ImageDataDefects, AreRefusedNamingTheLine) {
  const std::string good = text(test::dataFile("formats/image_ascii.vti"));
  const auto path = (std::filesystem::temp_directory_path() / "volpost_bad.vti").string();
  const auto refused = [&](const std::string& from, const std::string& to, const std::string& words) {
    std::string bad = good;
    const auto at = bad.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    bad.replace(at, from.size(), to);
    std::ofstream(path, std::ios::binary) << bad;
    try {
      (void)VtiReader().read(path, {});
      ADD_FAILURE() << "read with " << to;
    } catch (const ReadError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
      EXPECT_GE(e.line(), 1) << e.what();
    }
  };
  // Text that does not fit the declared type is kept as written, not clamped.
  {
    std::string odd = good;
    const std::string from = "type=\"Int32\" Name=\"material\" format=\"ascii\" RangeMin=\"0\" RangeMax=\"2\">\n        0 1 2";
    ASSERT_NE(odd.find(from), std::string::npos);
    odd.replace(odd.find(from), from.size(), "type=\"Int8\" Name=\"material\" format=\"ascii\">\n        0 300 2.5");
    std::ofstream(path, std::ios::binary) << odd;
    const auto model = VtiReader().read(path, {});
    const Field* material = model->findField("material");
    ASSERT_TRUE(material);
    EXPECT_EQ(material->samples(0).type(), SampleType::Float64);
    EXPECT_EQ(material->values(0)[1], 300.0);
    EXPECT_EQ(material->values(0)[2], 2.5);
    EXPECT_EQ(material->values(0)[3], 0.0);
  }
  refused("WholeExtent=\"1 5 0 3 2 4\"", "WholeExtent=\"1 5 0 3 2\"", "needs 6");
  refused("WholeExtent=\"1 5 0 3 2 4\"", "WholeExtent=\"1 5 0 3 4 4\"", "not 2D images");
  refused("Piece Extent=\"1 5 0 3 2 4\"", "Piece Extent=\"1 5 0 3 2 9\"", "outside the WholeExtent");
  refused("Spacing=\"0.5 0.25 2\"", "Spacing=\"0.5 0 2\"", "spacing 0");
  refused("Spacing=\"0.5 0.25 2\"", "Spacing=\"0.5 nan 2\"", "finite");
  refused("Name=\"temperature\" format=\"ascii\"", "Name=\"temperature\" NumberOfComponents=\"2\" format=\"ascii\"",
          "holds 60 values");
  std::filesystem::remove(path);
}

class LegacyStructuredPoints : public ::testing::TestWithParam<const char*> {};

TEST_P(LegacyStructuredPoints, ReadAsARegularGrid) {
  const auto model = VtkLegacyReader().read(test::dataFile(std::string("formats/") + GetParam()), {});
  ASSERT_TRUE(model->grid);
  const RegularGrid& g = *model->grid;
  EXPECT_EQ(g.dims, (std::array<std::size_t, 3>{5, 4, 3}));
  EXPECT_EQ(g.origin, glm::dvec3(10.0, -2.0, 0.5));
  EXPECT_EQ(g.axes[0], glm::dvec3(0.5, 0, 0));
  EXPECT_EQ(g.axes[2], glm::dvec3(0, 0, 2.0));
  const Field* temperature = model->findField("temperature");
  const Field* material = model->findField("material");
  ASSERT_TRUE(temperature && material);
  EXPECT_EQ(temperature->values(0)[g.pointIndex(3, 2, 1)], 223.0);
  EXPECT_EQ(material->values(0)[7], 1.0);
  // Kept in the file's types, as the other grid readers keep them.
  ASSERT_TRUE(temperature->storesSamples() && material->storesSamples());
  EXPECT_EQ(temperature->samples(0).type(), SampleType::Float64);
  EXPECT_EQ(material->samples(0).type(), SampleType::Int32);
}

// A 16-bit grid holds 2 bytes a sample, not the 8 of a double; text that does not fit its
// declared type is kept as written.
TEST(LegacyStructuredPoints, KeepSixteenBitSamplesAndWidenWhatDoesNotFit) {
  const auto path = (std::filesystem::temp_directory_path() / "volpost_points_short.vtk").string();
  std::string file = "# vtk DataFile Version 3.0\nshort\nBINARY\nDATASET STRUCTURED_POINTS\nDIMENSIONS 3 2 2\n"
                     "SPACING 1 1 1\nORIGIN 0 0 0\nPOINT_DATA 12\nSCALARS amplitude short 1\nLOOKUP_TABLE default\n";
  for (int i = 0; i < 12; ++i) {
    const std::int16_t v = std::int16_t(-30000 + 5000 * i);
    file += char((std::uint16_t(v) >> 8) & 0xff);  // big-endian, as legacy VTK writes
    file += char(std::uint16_t(v) & 0xff);
  }
  file += "\n";
  std::ofstream(path, std::ios::binary) << file;
  const auto model = VtkLegacyReader().read(path, {});
  const Field* amplitude = model->findField("amplitude");
  ASSERT_TRUE(amplitude && amplitude->storesSamples());
  EXPECT_EQ(amplitude->samples(0).type(), SampleType::Int16);
  EXPECT_EQ(amplitude->samples(0).bytes(), 24u);
  EXPECT_EQ(amplitude->values(0)[11], 25000.0);
  EXPECT_EQ(amplitude->values(0)[0], -30000.0);

  std::string text = "# vtk DataFile Version 3.0\nbytes\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 2 2 2\n"
                     "SPACING 1 1 1\nORIGIN 0 0 0\nPOINT_DATA 8\nSCALARS level unsigned_char 1\nLOOKUP_TABLE default\n"
                     "0 1 2 3 4 5 6 255\nSCALARS over unsigned_char 1\nLOOKUP_TABLE default\n0 1 2 3 4 5 6 300\n";
  std::ofstream(path, std::ios::binary) << text;
  const auto ascii = VtkLegacyReader().read(path, {});
  EXPECT_EQ(ascii->findField("level")->samples(0).type(), SampleType::UInt8);
  EXPECT_EQ(ascii->findField("level")->values(0)[7], 255.0);
  EXPECT_EQ(ascii->findField("over")->samples(0).type(), SampleType::Float64);
  EXPECT_EQ(ascii->findField("over")->values(0)[7], 300.0);
  std::filesystem::remove(path);
}

INSTANTIATE_TEST_SUITE_P(Encodings, LegacyStructuredPoints,
                         ::testing::Values("image_points_ascii.vtk", "image_points_binary.vtk"));

TEST(LegacyStructuredPointsDefects, AreRefusedNamingTheLine) {
  const std::string good = text(test::dataFile("formats/image_points_ascii.vtk"));
  const auto path = (std::filesystem::temp_directory_path() / "volpost_bad_points.vtk").string();
  for (const auto& [from, to, words] : {std::tuple{"DIMENSIONS 5 4 3", "DIMENSIONS 5 4 1", "not 2D images"},
                                        std::tuple{"SPACING 0.5 0.25 2", "SPACING 0.5 0.25 x", "is not a number"},
                                        std::tuple{"ORIGIN 10 -2 0.5", "POINTS 3 float", "in a STRUCTURED_POINTS file"},
                                        std::tuple{"CELL_DATA 24", "CELL_DATA 25", "does not match the 24 cells"}}) {
    std::string bad = good;
    bad.replace(bad.find(from), std::string(from).size(), to);
    std::ofstream(path, std::ios::binary) << bad;
    try {
      (void)VtkLegacyReader().read(path, {});
      ADD_FAILURE() << "read with " << to;
    } catch (const ReadError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace volpost::meshio
