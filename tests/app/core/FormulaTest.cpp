// SPDX-License-Identifier: MIT
// The calculator: formulas over quantities, coordinates, whole vector and tensor fields,
// pinned steps and envelopes, per node and per cell, checked value by value against the
// same arithmetic written out here; and every kind of bad formula named with its place.
#include "core/Formula.hpp"
#include "core/ModelSession.hpp"

#include <volpost/core/Quantity.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

using namespace volpost;
using namespace volpost::app;

namespace {

// Two tetrahedra sharing a face; per node T = x + 2y (step 1) and ten times that (step 2),
// U = (n, 2n, 3n) and twice that, S = diag(n, -n, 0) + xy = 1 and twice that; per cell a
// "heat flux" of 5 and 7; "mode" per node with three steps.
std::shared_ptr<ModelSession> smallModel() {
  auto model = std::make_shared<Model>();
  model->sourcePath = "two_tets";
  Mesh& mesh = model->mesh();
  mesh.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  const NodeIndex a[4] = {0, 1, 2, 3}, b[4] = {1, 2, 3, 4};
  mesh.addCell(CellType::Tet4, a);
  mesh.addCell(CellType::Tet4, b);
  const std::vector<Step> two = {{"load 1", 1.0}, {"load 2", 2.0}};
  std::vector<double> t1, u1, s1;
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
    t1.push_back(mesh.nodes[n].x + 2.0 * mesh.nodes[n].y);
    for (double k : {1.0, 2.0, 3.0}) u1.push_back(k * double(n));
    for (double v : {double(n), -double(n), 0.0, 1.0, 0.0, 0.0}) s1.push_back(v);
  }
  auto times = [](std::vector<double> v, double f) {
    for (double& x : v) x *= f;
    return v;
  };
  model->fields.push_back(Field::fromValues("T", FieldLocation::Node, 1, {t1, times(t1, 10.0)}, two));
  model->fields.push_back(Field::fromValues("U", FieldLocation::Node, 3, {u1, times(u1, 2.0)}, two));
  model->fields.push_back(Field::fromValues("S", FieldLocation::Node, 6, {s1, times(s1, 2.0)}, two));
  model->fields.push_back(Field::fromValues("heat flux", FieldLocation::Cell, 1, {{5.0, 7.0}}));
  model->fields.push_back(Field::fromValues("mode", FieldLocation::Node, 1, {t1, t1, t1},
                                            {{"mode 1", 0.0}, {"mode 2", 0.0}, {"mode 3", 0.0}}));
  return ModelSession::fromModel(model);
}

const Field& formula(const std::shared_ptr<ModelSession>& base, const std::string& name, const std::string& expr,
                     std::shared_ptr<ModelSession>& holder) {
  holder = ModelSession::withFormulas(*base, {{name, expr}});
  return *holder->model().findField(name);
}

std::string errorOf(const std::string& name, const std::string& expr) {
  const auto base = smallModel();
  try {
    ModelSession::withFormulas(*base, {{name, expr}});
  } catch (const FormulaError& e) {
    return e.what();
  }
  return "no error";
}

void expectHas(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "missing '" << part << "' in: " << text;
}

}  // namespace

TEST(Formula, ScalarOfQuantitiesAndCoordinatesHasTheStepsOfWhatItReads) {
  const auto base = smallModel();
  std::shared_ptr<ModelSession> s;
  const Field& f = formula(base, "r", "T / 2 + x - U.magnitude", s);
  ASSERT_EQ(f.location(), FieldLocation::Node);
  ASSERT_EQ(f.kind(), FieldKind::Scalar);
  ASSERT_EQ(f.stepCount(), 2u);
  EXPECT_EQ(f.steps()[1].label, "load 2");
  const Model& m = base->model();
  for (std::size_t step = 0; step < 2; ++step)
    for (std::size_t n = 0; n < 5; ++n) {
      const glm::dvec3 p = m.mesh().nodes[n];
      const double t = (p.x + 2.0 * p.y) * (step ? 10.0 : 1.0);
      const double u = double(n) * std::sqrt(14.0) * (step ? 2.0 : 1.0);
      EXPECT_NEAR(f.values(step)[n], t / 2.0 + p.x - u, 1e-12) << "node " << n << " step " << step;
    }
}

TEST(Formula, ConditionalsAndFunctionsAsWritten) {
  const auto base = smallModel();
  std::shared_ptr<ModelSession> s;
  const Field& c = formula(base, "c", "x > 0 ? T : -1", s);
  EXPECT_EQ(c.values(0), (std::vector<double>{-1, 1, -1, -1, 3}));
  std::shared_ptr<ModelSession> s2;
  const Field& h = formula(base, "h", "sqrt(U.x^2 + U.y^2)", s2);
  EXPECT_NEAR(h.values(1)[3], std::sqrt(36.0 + 144.0), 1e-12);
}

TEST(Formula, WholeTensorFieldsCombineComponentByComponent) {
  // A load-case combination is a tensor: its von Mises is that of the sum, not the sum of
  // von Mises values.
  const auto base = smallModel();
  std::shared_ptr<ModelSession> s;
  const Field& combo = formula(base, "combo", "1.35*S@1 + 1.5*S@2", s);
  ASSERT_EQ(combo.kind(), FieldKind::SymTensor);
  ASSERT_EQ(combo.stepCount(), 1u);
  const double k = 1.35 + 1.5 * 2.0;
  const double node3[6] = {3 * k, -3 * k, 0, k, 0, 0};
  for (int c = 0; c < 6; ++c) EXPECT_NEAR(combo.values(0)[3 * 6 + c], node3[c], 1e-12) << c;
  const Quantity mises = *parseQuantity("combo.mises", combo);
  EXPECT_NEAR(evaluate(combo, mises, 0)[3], vonMises(node3), 1e-12);

  std::shared_ptr<ModelSession> s2;
  const Field& du = formula(base, "du", "U@2 - U@1", s2);
  ASSERT_EQ(du.kind(), FieldKind::Vector);
  EXPECT_EQ(du.values(0)[3 * 4 + 2], 12.0);  // node 4: z 24 - 12
  std::shared_ptr<ModelSession> s3;
  const Field& scaled = formula(base, "scaled", "U * 1000", s3);  // follows U's steps
  EXPECT_EQ(scaled.stepCount(), 2u);
  EXPECT_EQ(scaled.values(1)[3 * 2 + 1], 8000.0);
}

TEST(Formula, EnvelopesOverStepsAndTheLastStep) {
  const auto base = smallModel();
  std::shared_ptr<ModelSession> s;
  const Field& low = formula(base, "low", "S.xx@min", s);
  ASSERT_EQ(low.stepCount(), 1u);
  EXPECT_EQ(low.values(0)[2], 2.0);  // node 2: xx 2 then 4
  std::shared_ptr<ModelSession> s2;
  const Field& peak = formula(base, "peak", "S.yy@max - T@last", s2);
  EXPECT_EQ(peak.values(0)[4], -4.0 - 30.0);  // yy -4 then -8; T at step 2 is 30
}

TEST(Formula, CommasBuildAVectorOrATensor) {
  const auto base = smallModel();
  std::shared_ptr<ModelSession> s;
  const Field& v = formula(base, "v", "U.x, -U.y, 0", s);
  ASSERT_EQ(v.kind(), FieldKind::Vector);
  EXPECT_EQ(v.values(1)[3 * 1 + 1], -4.0);
  std::shared_ptr<ModelSession> s2;
  const Field& t = formula(base, "t", "T, T, T, 0, 0, 0", s2);
  EXPECT_EQ(t.kind(), FieldKind::SymTensor);
}

TEST(Formula, APerCellFieldMakesAPerCellResultWithNodeValuesAveraged) {
  const auto base = smallModel();
  std::shared_ptr<ModelSession> s;
  const Field& q = formula(base, "q", "heat_flux * T + z", s);
  ASSERT_EQ(q.location(), FieldLocation::Cell);
  ASSERT_EQ(q.entityCount(), 2u);
  // cell 0: nodes 0..3, T = 0, 1, 2, 0 (mean 0.75), centroid z 0.25; cell 1: T = 1, 2, 0, 3
  EXPECT_NEAR(q.values(0)[0], 5.0 * 0.75 + 0.25, 1e-12);
  EXPECT_NEAR(q.values(1)[1], 7.0 * 15.0 + 0.5, 1e-12);
}

TEST(Formula, TheStepTimeAndFormulasReadingEarlierOnes) {
  const auto base = smallModel();
  const auto s = ModelSession::withFormulas(*base, {{"a", "T * time"}, {"b", "a + 1"}});
  EXPECT_EQ(s->model().findField("a")->values(1)[4], 30.0 * 2.0);
  EXPECT_EQ(s->model().findField("b")->values(1)[4], 61.0);
  ASSERT_EQ(s->formulas().size(), 2u);
  // New formulas replace the old ones, the file's fields stay.
  const auto again = ModelSession::withFormulas(*s, {{"c", "T"}});
  EXPECT_EQ(again->model().fields.size(), base->model().fields.size() + 1);
  EXPECT_EQ(again->model().findField("a"), nullptr);
  // The mesh's boundary is worked out once for both.
  EXPECT_EQ(&again->surface(), &base->surface());
}

TEST(Formula, DivisionByZeroGivesInfinityNotACrash) {
  const auto base = smallModel();
  std::shared_ptr<ModelSession> s;
  const Field& f = formula(base, "f", "T / 0", s);
  EXPECT_TRUE(std::isinf(f.values(0)[1]));
  EXPECT_TRUE(std::isnan(f.values(0)[0]));  // 0 / 0
}

TEST(Formula, BadFormulasSayWhatAndWhere) {
  expectHas(errorOf("r", "S.mizes / 2"), "no quantity or field named 'S.mizes' at character 1");
  expectHas(errorOf("r", "T +* 3"), "at character 4 of \"T +* 3\"");
  expectHas(errorOf("r", "sqrt(T"), "formula 'r':");
  expectHas(errorOf("r", "T *+"), "ends with '+', where a value must follow at character 4");
  expectHas(errorOf("r", "T *"), "Unexpected end of expression at character");
  expectHas(errorOf("r", "T = 3"), "'=' would assign at character 3");
  EXPECT_EQ(errorOf("r", "T == 3 || T >= 1 && T != 2"), "no error");
  expectHas(errorOf("r", "T@5"), "asks for step 5 of T, which has 2 steps");
  expectHas(errorOf("r", "T@x"), "after @ in 'T@x' comes a step number, last, max or min");
  expectHas(errorOf("r", "mode + T"), "has 3 steps and T 2");
  expectHas(errorOf("r", "U + S"), "reads whole fields of");
  expectHas(errorOf("r", "U@max"), "needs a quantity");
  expectHas(errorOf("r", "U * 2, 1"), "one value per component");
  expectHas(errorOf("r", "1,2,3,4,5,6,7,8,9,10"), "gives 10 values");
  expectHas(errorOf("r", "x@2"), "takes no @");
  expectHas(errorOf("r", "   "), "the expression is empty");
  expectHas(errorOf("r", std::string(5000, '1')), "at most 4096");
  expectHas(errorOf("2r", "T"), "use a letter or _ first");
  expectHas(errorOf("T", "1"), "already has a field named 'T'");
  expectHas(errorOf("heat_flux", "1"), "already has a field named 'heat flux'");
  expectHas(errorOf("sin", "1"), "taken by a function");
  expectHas(errorOf("x", "1"), "taken by the coordinates");
  const auto base = smallModel();
  EXPECT_THROW(ModelSession::withFormulas(*base, {{"a", "T"}, {"a", "U.x"}}), FormulaError);
}

TEST(Formula, DeepNestingIsReadOrRefusedNeverACrash) {
  const std::string deep = std::string(2000, '(') + "T" + std::string(2000, ')');
  const auto base = smallModel();
  try {
    const auto s = ModelSession::withFormulas(*base, {{"d", deep}});
    EXPECT_EQ(s->model().findField("d")->values(0)[4], 3.0);
  } catch (const FormulaError& e) {
    expectHas(e.what(), "formula 'd'");
  }
}

TEST(Formula, TheCommandLineFormOfAFormula) {
  const FormulaSpec f = parseFormulaText(" ratio = S.mises / 250 ");
  EXPECT_EQ(f.name, "ratio");
  EXPECT_EQ(f.expression, "S.mises / 250");
  EXPECT_THROW(parseFormulaText("S.mises / 250"), FormulaError);
  EXPECT_THROW(parseFormulaText("ratio="), FormulaError);
  EXPECT_EQ(formulaName("phase (degrees)"), "phase__degrees_");
  const auto names = formulaNames(smallModel()->model());
  for (const char* n : {"T", "U", "U.x", "S", "S.mises", "heat_flux", "x", "time"})
    EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
}
