// SPDX-License-Identifier: MIT
// One DataArray decoded where it lies: in the file's bytes in memory, or in the file on
// disk (a large file is not read whole), with the same values either way, in each encoding.
#include "VtuDataArray.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

using namespace volpost::meshio;

namespace {

std::string littleEndian(std::uint64_t header, const std::vector<double>& values) {
  std::string out(reinterpret_cast<const char*>(&header), 8);
  out.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(double));
  return out;
}

VtuEncoding uint64Headers() {
  VtuEncoding enc;
  enc.headerType = volpost::meshio::NumericType::UInt64;
  return enc;
}

}  // namespace

TEST(VtuDataArray, AnAppendedArrayIsDecodedFromItsOwnRunInMemoryOrOnDisk) {
  const std::vector<double> first = {1.0, 2.0}, second = {1.5, -2.0, 3.25};
  const std::string block = littleEndian(16, first) + littleEndian(24, second) + std::string(1000, 'x');
  const std::string file = "<VTKFile>..._" + block + "</VTKFile>";
  VtuArraySource s;
  s.name = "second";
  s.format = VtuArraySource::Format::Appended;
  s.file = std::make_shared<const std::string>(file);
  s.begin = 13;
  s.end = 13 + 24 + 32;     // its run: up to the next array (here, its own end)
  s.appendedOffset = 24;  // after the first array: 8 + 16 bytes
  const VtuEncoding enc = uint64Headers();
  EXPECT_EQ(vtuDoubles(s, enc), second);
  EXPECT_EQ(vtuValueCount(s, enc), 3u);
  EXPECT_THROW(vtuIntegers(s, enc), VtuArrayError) << "floating arrays are not integers";

  const auto path = std::filesystem::temp_directory_path() / "volpost_data_array_on_disk.vtu";
  std::ofstream(path, std::ios::binary) << file;
  VtuArraySource d = s;
  d.file = nullptr;
  d.disk = std::make_shared<const DiskFile>(path.string());
  EXPECT_EQ(vtuDoubles(d, enc), second);
  EXPECT_EQ(vtuValueCount(d, enc), 3u);
  d.end = d.begin + 24 + 20;  // a run cut short: the header's 24 bytes are not all there
  try {
    (void)vtuDoubles(d, enc);
    ADD_FAILURE() << "a cut-short run was decoded";
  } catch (const VtuArrayError& e) {
    EXPECT_NE(e.message.find("cut short"), std::string::npos) << e.message;
  }
  std::filesystem::remove(path);
}

TEST(VtuDataArray, InlineBase64AndAsciiArraysKeepTheirValues) {
  const VtuEncoding enc = uint64Headers();
  VtuArraySource b;
  b.name = "b64";
  b.format = VtuArraySource::Format::Binary;
  const std::string text = "GAAAAAAAAAAAAAAAAAD4PwAAAAAAAADAAAAAAAAACkA=";  // header 24, then 1.5 -2 3.25
  b.file = std::make_shared<const std::string>("<DataArray>" + text + "</DataArray>" + std::string(500, ' '));
  b.begin = 11;
  b.end = 11 + text.size();
  EXPECT_EQ(vtuDoubles(b, enc), (std::vector<double>{1.5, -2.0, 3.25}));
  VtuArraySource a = b;
  a.format = VtuArraySource::Format::Ascii;
  a.file = std::make_shared<const std::string>("<DataArray> 4 5.5 -6 </DataArray>");
  a.begin = 11;
  a.end = 21;
  EXPECT_EQ(vtuDoubles(a, enc), (std::vector<double>{4.0, 5.5, -6.0}));
}
