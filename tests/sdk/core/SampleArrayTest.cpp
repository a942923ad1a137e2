// SPDX-License-Identifier: MIT
// Values kept in their file's type: exact round trips, what fits, widening, and fields that
// hand them out without keeping a double copy.
#include <volpost/core/Field.hpp>
#include <volpost/core/Quantity.hpp>
#include <volpost/core/SampleArray.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace volpost;

TEST(SampleArray, EveryTypeKeepsWhatFitsAndSaysWhatDoesNot) {
  struct Case {
    SampleType type;
    double largest, smallest;
    std::size_t bytes;
  };
  for (const Case c : {Case{SampleType::Int8, 127, -128, 1}, Case{SampleType::UInt8, 255, 0, 1},
                       Case{SampleType::Int16, 32767, -32768, 2}, Case{SampleType::UInt16, 65535, 0, 2},
                       Case{SampleType::Int32, 2147483647.0, -2147483648.0, 4},
                       Case{SampleType::UInt32, 4294967295.0, 0, 4}}) {
    SCOPED_TRACE(toString(c.type));
    SampleArray a(c.type, 4);
    EXPECT_EQ(a.type(), c.type);
    EXPECT_EQ(a.bytes(), 4 * c.bytes);
    EXPECT_TRUE(a.fitsExactly(c.largest));
    EXPECT_TRUE(a.fitsExactly(c.smallest));
    EXPECT_FALSE(a.fitsExactly(c.largest + 1));
    EXPECT_FALSE(a.fitsExactly(c.smallest - 1));
    EXPECT_FALSE(a.fitsExactly(0.5));
    EXPECT_FALSE(a.fitsExactly(std::nan("")));
    a.set(0, c.largest);
    a.set(1, c.smallest);
    a.set(2, c.largest + 1000);  // clamped, not undefined
    a.set(3, std::nan(""));      // an integer has no NaN: 0
    EXPECT_EQ(a.toDoubles(), (std::vector<double>{c.largest, c.smallest, c.largest, 0.0}));
  }
  SampleArray f(SampleType::Float32, 3);
  EXPECT_TRUE(f.fitsExactly(0.5));
  EXPECT_FALSE(f.fitsExactly(0.1));
  EXPECT_FALSE(f.fitsExactly(1e40));
  EXPECT_TRUE(f.fitsExactly(std::nan("")));
  f.set(0, 0.5);
  f.set(1, -3.25e20);
  f.set(2, std::nan(""));
  const SampleArray d = f.widenedTo(SampleType::Float64);
  EXPECT_EQ(d.type(), SampleType::Float64);
  EXPECT_EQ(d[0], 0.5);
  EXPECT_EQ(d[1], double(float(-3.25e20)));
  EXPECT_TRUE(std::isnan(d[2]));
  EXPECT_TRUE(d.fitsExactly(0.1));
  EXPECT_THROW((void)f.widenedTo(SampleType::Int8), std::invalid_argument);
}

TEST(SampleArray, AFieldOfSamplesIsEvaluatedWithoutKeepingDoubles) {
  SampleArray s(SampleType::Int16, 1000);
  for (std::size_t i = 0; i < s.size(); ++i) s.set(i, double(int(i) - 500));
  int loads = 0;
  const auto field = Field::fromSamples("amplitude", FieldLocation::Node, 1, s.size(), {{"", 0.0}},
                                        [&loads, s](std::size_t) {
                                          ++loads;
                                          return s;
                                        });
  ASSERT_TRUE(field->storesSamples());
  const Quantity q = quantitiesOf(*field).front();
  const std::vector<double> values = evaluate(*field, q, 0);
  ASSERT_EQ(values.size(), 1000u);
  EXPECT_EQ(values[0], -500.0);
  EXPECT_EQ(values[999], 499.0);
  EXPECT_FALSE(field->isLoaded(0)) << "no double copy kept by the field";
  EXPECT_EQ(field->valuesCopy(0), values);
  EXPECT_FALSE(field->isLoaded(0));
  EXPECT_EQ(field->values(0), values) << "values() converts, and keeps that copy";
  EXPECT_TRUE(field->isLoaded(0));
  EXPECT_EQ(loads, 1) << "the samples are read once";
  EXPECT_EQ(field->samples(0).type(), SampleType::Int16);

  const auto plain = Field::fromValues("plain", FieldLocation::Node, 1, {{1.0, 2.0}});
  EXPECT_FALSE(plain->storesSamples());
  EXPECT_THROW((void)plain->samples(0), std::logic_error);
}

TEST(SampleArray, FieldFromValuesKeepsTheGivenVectorWithoutACopy) {
  std::vector<double> v(4096, 1.5);
  const double* data = v.data();
  std::vector<std::vector<double>> steps;
  steps.push_back(std::move(v));
  const auto field = Field::fromValues("f", FieldLocation::Cell, 1, std::move(steps));
  EXPECT_TRUE(field->isLoaded(0));
  EXPECT_EQ(field->values(0).data(), data);
  EXPECT_THROW((void)Field::fromValues("g", FieldLocation::Node, 1, {{1.0, 2.0}, {1.0}}), std::invalid_argument);
}

// The view the renderers and panels read: every type's values as doubles, the loop per type
// over the same memory, and doubles converted only where a double span is asked for.
TEST(SampleView, ReadsEveryTypeInPlace) {
  for (const SampleType type : {SampleType::Int8, SampleType::UInt8, SampleType::Int16, SampleType::UInt16,
                                SampleType::Int32, SampleType::UInt32, SampleType::Float32, SampleType::Float64}) {
    SCOPED_TRACE(toString(type));
    SampleArray a(type, 3);
    a.set(0, 7.0), a.set(1, 100.0), a.set(2, 0.0);
    const SampleView view(a);
    EXPECT_EQ(view.type(), type);
    EXPECT_EQ(view.size(), 3u);
    EXPECT_EQ(view.bytes(), a.bytes());
    EXPECT_EQ(view[0], 7.0);
    EXPECT_EQ(view[1], 100.0);
    double sum = 0.0;
    std::size_t bytesPerValue = 0;
    view.visit([&](auto typed) {
      bytesPerValue = sizeof(typed[0]);
      for (const auto v : typed) sum += double(v);
    });
    EXPECT_EQ(sum, 107.0);
    EXPECT_EQ(bytesPerValue, bytesPerSample(type)) << "visit hands out the stored type";
    std::vector<double> scratch;
    const std::span<const double> doubles = view.doubles(scratch);
    EXPECT_EQ(std::vector<double>(doubles.begin(), doubles.end()), (std::vector<double>{7.0, 100.0, 0.0}));
    EXPECT_EQ(scratch.empty(), type == SampleType::Float64) << "doubles are not copied";
  }
  const std::vector<double> values = {1.5, NAN};
  const SampleView ofDoubles(values);
  EXPECT_EQ(ofDoubles.type(), SampleType::Float64);
  EXPECT_TRUE(std::isnan(ofDoubles[1]));
  const ValueRange r = rangeOf(ofDoubles);
  EXPECT_EQ(r.finiteCount, 1u);
  EXPECT_EQ(r.nanCount, 1u);
  EXPECT_TRUE(SampleView().empty());
}
