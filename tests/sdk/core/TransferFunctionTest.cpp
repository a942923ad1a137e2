// SPDX-License-Identifier: MIT
#include <volpost/core/TransferFunction.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace volpost;

TEST(TransferFunction, InterpolatesAndClampsAtTheEnds) {
  const TransferFunction tf({{10.0, {1, 0, 0}, 4.0}, {0.0, {0, 0, 1}, 0.0}});
  EXPECT_EQ(tf.points().front().value, 0.0);  // sorted
  EXPECT_DOUBLE_EQ(tf.extinction(2.5), 1.0);
  EXPECT_EQ(tf.color(5.0), glm::dvec3(0.5, 0.0, 0.5));
  EXPECT_DOUBLE_EQ(tf.extinction(-3.0), 0.0);
  EXPECT_DOUBLE_EQ(tf.extinction(30.0), 4.0);
}

TEST(TransferFunction, OpacityAndExtinctionConvertBothWays) {
  for (double alpha : {0.0, 1e-9, 0.1, 0.5, 0.999999}) {
    const double tau = opacityToExtinction(alpha, 2.5);
    EXPECT_NEAR(extinctionToOpacity(tau, 2.5), alpha, 1e-15);
  }
  EXPECT_NEAR(opacityToExtinction(1.0 - std::exp(-1.0), 1.0), 1.0, 1e-15);
  EXPECT_THROW(opacityToExtinction(1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(opacityToExtinction(0.5, 0.0), std::invalid_argument);
}

TEST(TransferFunction, RejectsInvalidPoints) {
  EXPECT_THROW(TransferFunction({ControlPoint{0.0, {1, 1, 1}, -1.0}}), std::invalid_argument);
  EXPECT_THROW(TransferFunction({ControlPoint{0.0, {1.5, 1, 1}, 1.0}}), std::invalid_argument);
  EXPECT_THROW(TransferFunction({ControlPoint{std::nan(""), {1, 1, 1}, 1.0}}), std::invalid_argument);
}

TEST(TransferFunction, JsonRoundTripsExactly) {
  const TransferFunction tf = TransferFunction::ramp(-3.5, 120.25, "viridis", 0.7, 17);
  EXPECT_EQ(TransferFunction::fromJson(tf.toJson("mm")), tf);
}

TEST(TransferFunction, JsonErrorsNameTheEntry) {
  const auto message = [](const std::string& text) {
    try {
      TransferFunction::fromJson(text);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message("{").find("JSON"), std::string::npos);
  EXPECT_NE(message(R"({"format":"other"})").find("not a volpost transfer function"), std::string::npos);
  EXPECT_NE(message(R"({"format":"volpost-tf","version":1,"points":[{"value":0,"color":[1,1],"extinction":1}]})")
                .find("points[0].color"),
            std::string::npos);
  EXPECT_NE(message(R"({"format":"volpost-tf","version":1,"points":[{"value":0,"color":[1,1,1],"extinction":-2}]})")
                .find("extinction"),
            std::string::npos);
  // The JSON library's own errors in a user's words: where, and no "[json.exception...]" tag;
  // a number beyond a double is one of them (it was not caught here before).
  const std::string truncated = message(R"({"format":"volpost-tf","version":1,"points":[)");
  EXPECT_NE(truncated.find("transfer function JSON: parse error at line 1"), std::string::npos) << truncated;
  const std::string overflow = message(R"({"format":"volpost-tf","version":1,"points":[{"value":0,"color":[1,1,1],"extinction":1e999}]})");
  EXPECT_NE(overflow.find("transfer function JSON: number overflow parsing '1e999'"), std::string::npos) << overflow;
  for (const std::string& m : {truncated, overflow}) EXPECT_EQ(m.find("json.exception"), std::string::npos) << m;
}

TEST(TransferFunction, ImportsParaViewPresetColorsOntoARange) {
  const std::string presets = R"([
    {"Name": "Other", "RGBPoints": [0, 0, 0, 0, 1, 1, 1, 1]},
    {"Name": "Cool to Warm", "ColorSpace": "Diverging",
     "RGBPoints": [-1, 0.23, 0.299, 0.754, 0, 0.865, 0.865, 0.865, 1, 0.706, 0.016, 0.15]}])";
  const TransferFunction opacity({{0.0, {1, 1, 1}, 0.0}, {100.0, {1, 1, 1}, 2.0}});
  const TransferFunction tf = opacity.withParaViewColors(presets, "Cool to Warm", std::pair{0.0, 100.0});
  EXPECT_NEAR(tf.color(0.0).b, 0.754, 1e-12);
  EXPECT_NEAR(tf.color(50.0).r, 0.865, 1e-12);
  EXPECT_NEAR(tf.color(100.0).r, 0.706, 1e-12);
  EXPECT_NEAR(tf.extinction(50.0), 1.0, 1e-12);  // the opacity shape is kept
  EXPECT_THROW(opacity.withParaViewColors(presets, "Missing"), std::runtime_error);
  EXPECT_THROW(opacity.withParaViewColors(R"({"RGBPoints": [0, 1, 1]})"), std::runtime_error);
}
