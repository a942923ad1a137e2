// SPDX-License-Identifier: MIT
// NRRD volumes written here byte by byte as the format's specification lays them out: the
// grid (space directions and origin, or spacings), every sample type and byte order, raw
// data attached or in a data file with skips, text, hex and gzip encodings, vector
// samples; and refusals that name the field, the line or the missing bytes.
#include "AllReaders.hpp"
#include "NrrdReader.hpp"

#include <volpost/core/Error.hpp>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <zlib.h>

#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

namespace volpost::meshio {
namespace {

namespace fs = std::filesystem;

class Nrrd : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("volpost_nrrd_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& bytes) const {
    const std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }

  template <typename T>
  static std::string samples(const std::vector<T>& values, bool bigEndian) {
    std::string out;
    for (T v : values) {
      char b[sizeof(T)];
      std::memcpy(b, &v, sizeof(T));
      if (bigEndian != (std::endian::native == std::endian::big)) std::reverse(b, b + sizeof(T));
      out.append(b, sizeof(T));
    }
    return out;
  }

  static std::unique_ptr<Model> read(const std::string& path) { return NrrdReader().read(path, {}); }

  static std::string readError(const std::string& path) {
    try {
      (void)read(path)->fields.at(0)->values(0);
    } catch (const ReadError& e) {
      return e.what();
    }
    return "no error";
  }

  fs::path dir_;
};

// 4 x 3 x 2 points, value = i + 10 j + 100 k.
std::vector<double> ramp() {
  std::vector<double> v;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i) v.push_back(i + 10 * j + 100 * k);
  return v;
}

template <typename T>
std::vector<T> as(const std::vector<double>& v) {
  return std::vector<T>(v.begin(), v.end());
}

TEST_F(Nrrd, ARotatedGridWithAttachedRawDataIsPlacedAndValuedAsTheHeaderSays) {
  const std::string header =
      "NRRD0004\n# written by a test\ntype: short\ndimension: 3\nspace: right-anterior-superior\nsizes: 4 3 2\n"
      "space directions: (0,0.5,0) (-2,0,0) (0,0,3)\nspace origin: (10,20,30)\nendian: big\nencoding: raw\n"
      "content: density\nkey:=value\n\n";
  const auto model = read(write("rotated.nrrd", header + samples(as<std::int16_t>(ramp()), true)));
  ASSERT_TRUE(model->grid);
  const RegularGrid& g = *model->grid;
  EXPECT_EQ(g.dims, (std::array<std::size_t, 3>{4, 3, 2}));
  EXPECT_EQ(g.origin, glm::dvec3(10, 20, 30));
  EXPECT_EQ(g.position(3, 2, 1), glm::dvec3(10 - 4, 20 + 1.5, 30 + 3));
  EXPECT_EQ(g.sampleStorage, "16-bit integer (NRRD raw, big-endian)");
  EXPECT_EQ(model->title, "density");
  ASSERT_EQ(model->fields.size(), 1u);
  EXPECT_EQ(model->fields[0]->name(), "density");
  EXPECT_EQ(model->fields[0]->values(0), ramp());
  EXPECT_EQ(model->mesh().cellCount(), 3u * 2u * 1u);
  EXPECT_EQ(model->formatName, "NRRD raw volume");
}

TEST_F(Nrrd, EverySampleTypeInBothByteOrders) {
  // The samples stay in the file's type (64-bit integers as 64-bit floats).
  const auto check = [&](const std::string& type, const std::string& data, bool big, const std::vector<double>& expected,
                         SampleType stored) {
    const std::string header = "NRRD0005\ntype: " + type + "\ndimension: 3\nsizes: 4 3 2\nencoding: raw\nendian: " +
                               (big ? "big" : "little") + "\nspacings: 1 1 1\n\n";
    const auto model = read(write("t.nrrd", header + data));
    ASSERT_TRUE(model->fields[0]->storesSamples());
    EXPECT_EQ(model->fields[0]->samples(0).type(), stored) << type;
    EXPECT_EQ(model->fields[0]->values(0), expected) << type << (big ? " big" : " little");
  };
  std::vector<double> signedRamp = ramp();
  for (double& v : signedRamp) v = v - 100.0;  // negative values too
  for (bool big : {false, true}) {
    check("int8", samples(as<std::int8_t>(signedRamp), big), big, signedRamp, SampleType::Int8);
    check("uchar", samples(as<std::uint8_t>(ramp()), big), big, ramp(), SampleType::UInt8);
    check("int16", samples(as<std::int16_t>(signedRamp), big), big, signedRamp, SampleType::Int16);
    check("unsigned short", samples(as<std::uint16_t>(ramp()), big), big, ramp(), SampleType::UInt16);
    check("int", samples(as<std::int32_t>(signedRamp), big), big, signedRamp, SampleType::Int32);
    check("uint32", samples(as<std::uint32_t>(ramp()), big), big, ramp(), SampleType::UInt32);
    check("long long", samples(as<std::int64_t>(signedRamp), big), big, signedRamp, SampleType::Float64);
    check("uint64", samples(as<std::uint64_t>(ramp()), big), big, ramp(), SampleType::Float64);
    check("float", samples(as<float>(signedRamp), big), big, signedRamp, SampleType::Float32);
    check("double", samples(signedRamp, big), big, signedRamp, SampleType::Float64);
  }
}

TEST_F(Nrrd, ADetachedHeaderWithSkipsSpacingsAndDataAtTheEnd) {
  write("data.raw", "two lines\nof preamble\n" + std::string(5, 'x') + samples(as<float>(ramp()), false));
  const auto model = read(write("volume.nhdr",
                                "NRRD0004\ntype: float\ndimension: 3\nsizes: 4 3 2\nspacings: 0.5 0.25 2\n"
                                "endian: little\nencoding: raw\ndata file: data.raw\nline skip: 2\nbyte skip: 5\n"));
  EXPECT_EQ(model->grid->axes[0], glm::dvec3(0.5, 0, 0));
  EXPECT_EQ(model->grid->axes[2], glm::dvec3(0, 0, 2));
  EXPECT_EQ(model->fields[0]->values(0), ramp());
  // byte skip -1: the samples are the file's last bytes, whatever comes before.
  const auto atEnd = read(write("end.nhdr", "NRRD0004\ntype: float\ndimension: 3\nsizes: 4 3 2\nendian: little\n"
                                           "encoding: raw\ndatafile: data.raw\nbyte skip: -1\n"));
  EXPECT_EQ(atEnd->fields[0]->values(0), ramp());
}

TEST_F(Nrrd, TextHexAndGzipEncodings) {
  std::string text;
  for (double v : ramp()) text += std::to_string(v) + (int(v) % 4 == 3 ? "\n" : " ");
  const auto fromText = read(write("t.nrrd", "NRRD0004\ntype: double\ndimension: 3\nsizes: 4 3 2\nencoding: ascii\n\n" + text));
  EXPECT_EQ(fromText->fields[0]->values(0), ramp());
  std::string hex;
  for (unsigned char c : samples(as<std::uint16_t>(ramp()), true)) {
    const char* digits = "0123456789abcdef";
    hex += digits[c >> 4];
    hex += digits[c & 15];
    hex += hex.size() % 33 == 32 ? "\n" : "";
  }
  const auto fromHex = read(write("h.nrrd", "NRRD0004\ntype: ushort\ndimension: 3\nsizes: 4 3 2\nendian: big\nencoding: hex\n\n" + hex));
  EXPECT_EQ(fromHex->fields[0]->values(0), ramp());
  // gzip, as gzwrite writes it.
  const std::string raw = samples(as<std::int32_t>(ramp()), false);
  const std::string gzPath = (dir_ / "data.raw.gz").string();
  gzFile gz = gzopen(gzPath.c_str(), "wb");
  ASSERT_TRUE(gz);
  gzwrite(gz, raw.data(), unsigned(raw.size()));
  gzclose(gz);
  const auto fromGzip = read(write("g.nhdr", "NRRD0004\ntype: int32\ndimension: 3\nsizes: 4 3 2\nendian: little\n"
                                              "encoding: gzip\ndata file: data.raw.gz\n"));
  EXPECT_EQ(fromGzip->fields[0]->values(0), ramp());
  // Cut short: the bytes it holds and the bytes it needs.
  std::ifstream in(gzPath, std::ios::binary);
  const std::string whole((std::istreambuf_iterator<char>(in)), {});
  write("data.raw.gz", whole.substr(0, whole.size() / 2));
  EXPECT_NE(readError((dir_ / "g.nhdr").string()).find("need"), std::string::npos) << readError((dir_ / "g.nhdr").string());
}

TEST_F(Nrrd, AFirstAxisOfComponentsGivesAVectorPerPoint) {
  std::vector<float> v;
  for (int p = 0; p < 24; ++p)
    for (int c = 0; c < 3; ++c) v.push_back(float(p * 10 + c));
  const auto model = read(write("v.nrrd", "NRRD0004\ntype: float\ndimension: 4\nsizes: 3 4 3 2\nkinds: vector domain domain domain\n"
                                          "space directions: none (1,0,0) (0,1,0) (0,0,1)\nendian: little\nencoding: raw\n\n" +
                                              samples(v, false)));
  EXPECT_EQ(model->grid->dims, (std::array<std::size_t, 3>{4, 3, 2}));
  ASSERT_EQ(model->fields[0]->components(), 3);
  EXPECT_EQ(model->fields[0]->kind(), FieldKind::Vector);
  EXPECT_EQ(model->fields[0]->values(0)[3 * 5 + 2], 52.0);
}

TEST_F(Nrrd, BadHeadersAndDataAreRefusedNamingWhatIsWrong) {
  const std::string base = "NRRD0004\ntype: float\ndimension: 3\nsizes: 4 3 2\nendian: little\nencoding: raw\n";
  const std::string data = samples(as<float>(ramp()), false);
  const auto refused = [&](const std::string& bytes, const std::string& expected) {
    const std::string message = readError(write("bad.nrrd", bytes));
    EXPECT_NE(message.find(expected), std::string::npos) << "expected '" << expected << "' in: " << message;
    EXPECT_NE(message.find("bad.nrrd"), std::string::npos) << message;
  };
  refused("NRRD0009\n", "NRRD0001 to NRRD0005");
  refused("P6\n4 3\n", "not an NRRD file");
  refused("NRRD0004\ndimension: 3\nsizes: 4 3 2\nencoding: raw\n\n", "no 'type:' line");
  refused("NRRD0004\ntype: complex\ndimension: 3\nsizes: 4 3 2\nencoding: raw\n\n", "type 'complex'");
  refused("NRRD0004\ntype: float\ndimension: 3\nsizes: 4 3\nencoding: raw\nendian: little\n\n", "sizes lists 2 axes");
  refused("NRRD0004\ntype: float\ndimension: 3\nsizes: 4 0 2\nencoding: raw\nendian: little\n\n", "not a positive whole number");
  refused("NRRD0004\ntype: float\ndimension: 3\nsizes: 4 3 2\nencoding: raw\n\n", "no 'endian:' line");
  refused("NRRD0004\ntype: float\ndimension: 3\nsizes: 4 3 2\nencoding: bzip2\nendian: little\n\n", "bzip2");
  refused("NRRD0004\ntype: float\ndimension: 2\nsizes: 4 3\nencoding: raw\nendian: little\n\n", "not a volume");
  refused("NRRD0004\ntype: float\ndimension: 3\nsizes: 4 3 1\nencoding: raw\nendian: little\n\n", "volumes");
  refused(base + "space directions: (1,0,0) (0,1,0)\n\n" + data, "space directions lists 2 axes");
  refused(base + "space directions: (1,0,0) (0,1,0) (0,nan,1)\n\n" + data, "not finite");
  refused(base + "space directions: (1,0,0) (0,1,0) (1,0,0)\n\n" + data, "volumes");  // flat: two axes alike
  refused(base + "space origin: (1,2)\n\n" + data, "3D space");
  refused(base + "type: double\n\n" + data, "given twice");
  refused(base + "\n" + data.substr(0, 50), "the data ends after 50 of the 96 bytes");
  refused(base + "data file: missing.raw\n", "missing.raw");
  refused(base + "data file: LIST\nslice1.raw\n", "several files");
  refused("NRRD0004\ntype: float\ndimension: 3\nsizes: 100000 100000 100000\nencoding: raw\nendian: little\n\n",
          "memory budget");
  refused("NRRD0004\ntype: uchar\ndimension: 3\nsizes: 4 3 2\nencoding: text\n\n1 2 3 oops", "'oops'");
  refused("NRRD0004\ntype: uchar\ndimension: 3\nsizes: 4 3 2\nencoding: text\n\n1 2 3", "3 of the 24 values");
  refused("NRRD0004\n" + std::string(2 << 20, 'a'), "no end of the header");
  refused("NRRD0004\ntype: float\nthis line has no colon\n", "bad.nrrd:3:");
}

TEST_F(Nrrd, TheRegistryPicksTheReaderByItsFirstBytes) {
  const std::string path = write("volume.dat", "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 4 3 2\nencoding: raw\n\n" +
                                                   samples(as<std::uint8_t>(ramp()), false));
  const auto model = allReadersRegistry().load(path);
  ASSERT_TRUE(model->grid);
  EXPECT_EQ(model->fields[0]->values(0), ramp());
}

}  // namespace
}  // namespace volpost::meshio

namespace volpost::meshio {
namespace {

TEST_F(Nrrd, TheDataFileReadLaterIsTheOneCheckedWhenOpened) {
  // The samples are read when first shown, from the descriptor opened with the header:
  // the data file reopened by name read whatever was there by then (a pipe swapped in
  // blocked for ever; a same-size rewrite went unnoticed).
  const std::string raw = write("later.raw", samples(as<float>(ramp()), false));
  const auto model = read(write("later.nhdr",
                                "NRRD0004\ntype: float\ndimension: 3\nsizes: 4 3 2\nendian: little\n"
                                "encoding: raw\ndata file: later.raw\n"));
  // Replaced by name with a file of the same size: the model still reads the one it checked.
  fs::rename(raw, raw + ".old");
  write("later.raw", std::string(24 * 4, '\0'));
  EXPECT_EQ(model->fields[0]->values(0), ramp());
}

TEST_F(Nrrd, DataRewrittenInPlaceIsRefusedWhenRead) {
  const std::string raw = write("inplace.raw", samples(as<float>(ramp()), false));
  const auto model = read(write("inplace.nhdr",
                                "NRRD0004\ntype: float\ndimension: 3\nsizes: 4 3 2\nendian: little\n"
                                "encoding: raw\ndata file: inplace.raw\n"));
  // Same size, other bytes, a later time: the values would belong to another file.
  fs::last_write_time(raw, fs::last_write_time(raw) - std::chrono::hours(1));
  { std::ofstream(raw, std::ios::binary | std::ios::in | std::ios::out) << std::string(8, '\x7f'); }
  try {
    (void)model->fields[0]->values(0);
    FAIL() << "read a changed file";
  } catch (const ReadError& e) {
    EXPECT_NE(std::string(e.what()).find("changed after it was opened"), std::string::npos) << e.what();
  }
}

TEST_F(Nrrd, ALineSkipPastTheEndAndConcatenatedGzipMembers) {
  EXPECT_NE(readError(write("skip.nrrd",
                            "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 4 3 2\nencoding: raw\n"
                            "line skip: 1\nbyte skip: 1\n\nno newline after this")),
            "no error");
  const std::string skipped = readError(write("skip2.nrrd",
                                              "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 4 3 2\n"
                                              "encoding: raw\nline skip: 3\n\none\ntwo"));
  EXPECT_NE(skipped.find("the data ends within the 3 lines the header's line skip passes over (1 found)"),
            std::string::npos)
      << skipped;
  // Two gzip members, 12 bytes each: read whole.
  const auto gzip = [](const std::string& bytes) {
    z_stream z{};
    deflateInit2(&z, 9, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY);
    std::string out(256, '\0');
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
    z.avail_in = uInt(bytes.size());
    z.next_out = reinterpret_cast<Bytef*>(out.data());
    z.avail_out = uInt(out.size());
    deflate(&z, Z_FINISH);
    out.resize(z.total_out);
    deflateEnd(&z);
    return out;
  };
  std::string bytes;
  for (int i = 0; i < 24; ++i) bytes += char(i);
  const auto model = read(write("two.nrrd", "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 4 3 2\nencoding: gzip\n\n" +
                                                gzip(bytes.substr(0, 12)) + gzip(bytes.substr(12))));
  ASSERT_EQ(model->fields[0]->values(0).size(), 24u);
  for (int i = 0; i < 24; ++i) EXPECT_EQ(model->fields[0]->values(0)[std::size_t(i)], double(i));
  // A header claiming far more than its compressed bytes can hold: refused before the memory.
  const std::string claim =
      readError(write("claim.nrrd",
                      "NRRD0004\ntype: double\ndimension: 3\nsizes: 1000 1000 100\nendian: little\n"
                      "encoding: gzip\n\n" +
                          gzip("tiny")));
  EXPECT_NE(claim.find("bytes of gzip data cannot hold the 800000000 bytes"), std::string::npos) << claim;
}

}  // namespace
}  // namespace volpost::meshio
