// SPDX-License-Identifier: MIT
// The 2D transfer function: its widgets' regions, the table the renderers integrate (zero
// beyond it, a ramp one node wide at a widget's edge, overlapping widgets adding their
// extinction and mixing their colors by it), its JSON both ways, and refusals naming the
// widget and the number.
#include <volpost/core/TransferFunction.hpp>
#include <volpost/core/TransferFunction2D.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace volpost;

namespace {

TfWidget2D rectangle(double value, double width, double g0, double g1, glm::dvec3 color, double extinction) {
  return {TfWidget2D::Shape::Rectangle, value, width, g0, g1, color, extinction};
}

}  // namespace

TEST(TransferFunction2D, WidgetsCoverTheirRegions) {
  const TfWidget2D box = rectangle(5.0, 2.0, 1.0, 3.0, {1, 0, 0}, 2.0);
  EXPECT_EQ(box.weight(5.0, 2.0), 1.0);
  EXPECT_EQ(box.weight(5.9, 1.1), 1.0);
  EXPECT_EQ(box.weight(6.1, 2.0), 0.0);
  EXPECT_EQ(box.weight(5.0, 0.5), 0.0);
  TfWidget2D triangle = box;
  triangle.shape = TfWidget2D::Shape::Triangle;  // apex at (5, 1), full width 2 at gradient 3
  EXPECT_EQ(triangle.weight(5.0, 2.0), 1.0);
  EXPECT_EQ(triangle.weight(5.4, 2.0), 1.0);  // half-width 0.5 at gradient 2
  EXPECT_EQ(triangle.weight(5.6, 2.0), 0.0);
  EXPECT_EQ(triangle.weight(5.9, 2.9), 1.0);
}

// The table is float (the GPU's): an extinction beyond float's range is held at
// kMaxFloatExtinction with its color, never as infinity (NaN colors in every renderer).
TEST(TransferFunction2D, AnExtinctionBeyondFloatIsCappedWithItsColor) {
  const TransferFunction2D tf({rectangle(5.0, 2.0, 1.0, 3.0, {1, 0.5, 0}, 1e300), rectangle(6.0, 2.0, 2.0, 4.0, {0, 0, 1}, 6.0)});
  for (const glm::vec4& node : tf.table()) ASSERT_TRUE(std::isfinite(node.r) && std::isfinite(node.a));
  const glm::dvec4 c = tf.evaluate(4.5, 1.5);
  EXPECT_NEAR(c.a, kMaxFloatExtinction, 1e-6 * kMaxFloatExtinction);
  EXPECT_NEAR(c.r, 1.0, 1e-6);
  EXPECT_NEAR(c.g, 0.5, 1e-6);
  EXPECT_TRUE(std::isfinite(tf.evaluate(5.5, 2.5).b));  // where the blue one overlaps: red-orange, finite
}

TEST(TransferFunction2D, TheTableIsWhatIsRendered) {
  const TransferFunction2D tf({rectangle(5.0, 2.0, 1.0, 3.0, {1, 0, 0}, 2.0), rectangle(6.0, 2.0, 2.0, 4.0, {0, 0, 1}, 6.0)});
  // Well inside one widget: its color and extinction.
  glm::dvec4 c = tf.evaluate(4.5, 1.5);
  EXPECT_NEAR(c.a, 2.0, 1e-6);
  EXPECT_NEAR(c.r, 1.0, 1e-6);
  // Where both cover: extinctions add, colors mix by extinction (1/4 red, 3/4 blue).
  c = tf.evaluate(5.5, 2.5);
  EXPECT_NEAR(c.a, 8.0, 1e-6);
  EXPECT_NEAR(c.r, 0.25, 1e-6);
  EXPECT_NEAR(c.b, 0.75, 1e-6);
  // Outside every widget, and beyond the table.
  EXPECT_EQ(tf.evaluate(6.5, 0.5).a, 0.0);
  EXPECT_EQ(tf.evaluate(100.0, 2.0).a, 0.0);
  EXPECT_EQ(tf.evaluate(5.0, 100.0).a, 0.0);
  EXPECT_LT(tf.valueLow(), 4.0);
  EXPECT_GT(tf.valueHigh(), 7.0);
  EXPECT_GT(tf.gradientHigh(), 4.0);
  // An edge is a ramp at most one node wide: the value halfway between the nodes around it.
  const double node = (tf.valueHigh() - tf.valueLow()) / (TransferFunction2D::kValueNodes - 1);
  for (double v = 3.9; v < 4.1; v += node / 7.0) {
    const double tau = tf.evaluate(v, 1.5).a;
    if (v < 4.0 - node) EXPECT_EQ(tau, 0.0) << v;
    if (v > 4.0 + node) EXPECT_NEAR(tau, 2.0, 1e-6) << v;
    EXPECT_TRUE(tau >= 0.0 && tau <= 2.0 + 1e-9);
  }
  EXPECT_EQ(TransferFunction2D().evaluate(5.0, 2.0).a, 0.0);
}

TEST(TransferFunction2D, JsonRoundTripAndRefusals) {
  TfWidget2D tri = rectangle(-0.5, 1.0, 0.0, 2.0, {0.2, 0.8, 0.4}, 3.5);
  tri.shape = TfWidget2D::Shape::Triangle;
  const TransferFunction2D tf({rectangle(5.0, 2.0, 1.0, 3.0, {1, 0, 0}, 2.0), tri});
  const TransferFunction2D back = TransferFunction2D::fromJson(tf.toJson());
  EXPECT_EQ(back, tf);
  EXPECT_EQ(back.table(), tf.table());
  const auto refusal = [](const std::string& json) {
    try {
      (void)TransferFunction2D::fromJson(json);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  const std::string head = R"({"format":"volpost-tf2d","version":1,"widgets":[)";
  EXPECT_NE(refusal("{"), "(accepted)");
  EXPECT_NE(refusal(R"({"format":"volpost-tf","version":1,"points":[]})").find("volpost-tf2d"), std::string::npos);
  EXPECT_NE(refusal(head + "]}").find("non-empty"), std::string::npos);
  EXPECT_NE(refusal(head + R"({"shape":"circle","value":1,"width":1,"gradient":[0,1],"color":[1,1,1],"extinction":1}]})")
                .find("widgets[0].shape"),
            std::string::npos);
  EXPECT_NE(refusal(head + R"({"shape":"rectangle","value":1,"width":0,"gradient":[0,1],"color":[1,1,1],"extinction":1}]})")
                .find("width 0"),
            std::string::npos);
  EXPECT_NE(refusal(head + R"({"shape":"rectangle","value":1,"width":1,"gradient":[2,1],"color":[1,1,1],"extinction":1}]})")
                .find("is empty"),
            std::string::npos);
  EXPECT_NE(refusal(head + R"({"shape":"rectangle","value":1,"width":1,"gradient":[0,1],"color":[1,2,1],"extinction":1}]})")
                .find("outside 0..1"),
            std::string::npos);
  EXPECT_NE(refusal(head + R"({"shape":"rectangle","value":1,"width":1,"gradient":[0,1],"color":[1,1,1],"extinction":-1}]})")
                .find("extinction"),
            std::string::npos);
  EXPECT_NE(refusal(head + R"({"shape":"rectangle","value":1,"width":1,"color":[1,1,1],"extinction":1}]})")
                .find("\"gradient\""),
            std::string::npos);
  EXPECT_THROW(TransferFunction2D(std::vector<TfWidget2D>(65, rectangle(0, 1, 0, 1, {1, 1, 1}, 1))), std::invalid_argument);
}
