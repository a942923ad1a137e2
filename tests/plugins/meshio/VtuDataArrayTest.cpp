// SPDX-License-Identifier: MIT
// One DataArray decoded where it lies in the file, and detached (a copy of its own bytes,
// so that a lazy field does not hold a large file in memory): the same values either way,
// in each encoding, and the detached copy holds only that array.
#include "VtuDataArray.hpp"

#include <gtest/gtest.h>

#include <cstring>
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

TEST(VtuDataArray, AnAppendedArrayDetachedKeepsItsValuesAndOnlyItsBytes) {
  const std::vector<double> first = {1.0, 2.0}, second = {1.5, -2.0, 3.25};
  const std::string block = littleEndian(16, first) + littleEndian(24, second) + std::string(1000, 'x');
  VtuArraySource s;
  s.name = "second";
  s.format = VtuArraySource::Format::Appended;
  s.file = std::make_shared<const std::string>("<VTKFile>..._" + block + "</VTKFile>");
  s.begin = 13;
  s.end = 13 + block.size();
  s.appendedOffset = 24;  // after the first array: 8 + 16 bytes
  const VtuEncoding enc = uint64Headers();
  EXPECT_EQ(vtuDoubles(s, enc), second);
  const VtuArraySource d = vtuDetached(s, enc);
  EXPECT_EQ(d.file->size(), 8u + 24u) << "its header and its three values, nothing else";
  EXPECT_EQ(vtuDoubles(d, enc), second);
  EXPECT_THROW(vtuIntegers(s, enc), VtuArrayError) << "floating arrays are not integers";
}

TEST(VtuDataArray, InlineBase64AndAsciiArraysDetachedKeepTheirValues) {
  const VtuEncoding enc = uint64Headers();
  VtuArraySource b;
  b.name = "b64";
  b.format = VtuArraySource::Format::Binary;
  const std::string text = "GAAAAAAAAAAAAAAAAAD4PwAAAAAAAADAAAAAAAAACkA=";  // header 24, then 1.5 -2 3.25
  b.file = std::make_shared<const std::string>("<DataArray>" + text + "</DataArray>" + std::string(500, ' '));
  b.begin = 11;
  b.end = 11 + text.size();
  EXPECT_EQ(vtuDoubles(vtuDetached(b, enc), enc), (std::vector<double>{1.5, -2.0, 3.25}));
  EXPECT_EQ(vtuDetached(b, enc).file->size(), text.size());
  VtuArraySource a = b;
  a.format = VtuArraySource::Format::Ascii;
  a.file = std::make_shared<const std::string>("<DataArray> 4 5.5 -6 </DataArray>");
  a.begin = 11;
  a.end = 21;
  EXPECT_EQ(vtuDoubles(vtuDetached(a, enc), enc), (std::vector<double>{4.0, 5.5, -6.0}));
}
