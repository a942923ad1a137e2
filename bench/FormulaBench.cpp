// SPDX-License-Identifier: MIT
// The calculator: how long a formula's field takes per step against the same arithmetic
// written in C++, and the largest difference between the two, on a synthetic model of N
// nodes (a stress and a displacement with two steps each). One thread, wall time.
// Prints a Markdown table.
//   volpost_formula_bench [--nodes N]
#include "BenchUsage.hpp"

#include "core/Formula.hpp"

#include <volpost/core/Quantity.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <random>
#include <string>

using namespace volpost;
using namespace volpost::app;
using Clock = std::chrono::steady_clock;

namespace {

double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

Model syntheticModel(std::size_t nodes) {
  Model model;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> value(-100.0, 100.0);
  Mesh& mesh = model.mesh();
  mesh.nodes.resize(nodes);
  for (auto& p : mesh.nodes) p = {value(random), value(random), value(random)};
  const std::vector<Step> steps = {{"load 1", 1.0}, {"load 2", 2.0}};
  std::vector<std::vector<double>> s(2), u(2);
  for (int k = 0; k < 2; ++k) {
    s[k].resize(nodes * 6);
    u[k].resize(nodes * 3);
    for (double& x : s[k]) x = value(random);
    for (double& x : u[k]) x = value(random) * 1e-3;
  }
  model.fields.push_back(Field::fromValues("S", FieldLocation::Node, 6, s, steps));
  model.fields.push_back(Field::fromValues("U", FieldLocation::Node, 3, u, steps));
  return model;
}

struct Case {
  const char* formula;
  std::function<std::vector<double>(const Model&)> direct;
};

}  // namespace

int main(int argc, char** argv) {
  std::size_t nodes = 1000000;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--nodes") && i + 1 < argc) nodes = std::stoul(argv[++i]);
    else
      return bench::usageFor(argv[i],
                             "volpost_formula_bench: formula fields against hand-written C++\n"
                             "  --nodes N   nodes of the synthetic model (default 1000000)\n");
  }
  Model model = syntheticModel(nodes);
  // The C++ side reads the values in memory already, as the formula's field does.
  const std::vector<double>& s0 = model.fields[0]->values(0);
  const std::vector<double>& s1 = model.fields[0]->values(1);
  const std::vector<double>& u0 = model.fields[1]->values(0);
  const std::vector<Case> cases = {
      {"S.mises / 250",
       [&](const Model&) {
         std::vector<double> out(nodes);
         for (std::size_t n = 0; n < nodes; ++n) out[n] = vonMises(&s0[6 * n]) / 250.0;
         return out;
       }},
      {"sqrt(U.x^2 + U.y^2)",
       [&](const Model&) {
         std::vector<double> out(nodes);
         for (std::size_t n = 0; n < nodes; ++n) out[n] = std::hypot(u0[3 * n], u0[3 * n + 1]);
         return out;
       }},
      {"x > 0 ? S.mises : 0",
       [&](const Model& m) {
         std::vector<double> out(nodes);
         for (std::size_t n = 0; n < nodes; ++n) out[n] = m.mesh().nodes[n].x > 0 ? vonMises(&s0[6 * n]) : 0;
         return out;
       }},
      {"1.35*S@1 + 1.5*S@2",
       [&](const Model&) {
         std::vector<double> out(nodes * 6);
         for (std::size_t i = 0; i < out.size(); ++i) out[i] = 1.35 * s0[i] + 1.5 * s1[i];
         return out;
       }},
      {"S.mises@max",
       [&](const Model&) {
         std::vector<double> out(nodes);
         for (std::size_t n = 0; n < nodes; ++n) out[n] = std::max(vonMises(&s0[6 * n]), vonMises(&s1[6 * n]));
         return out;
       }},
  };
  std::printf("Formula fields, %zu nodes, one step, one thread (wall time)\n\n", nodes);
  std::printf("| formula | volpost ms | C++ ms | ratio | ns/value | max abs difference |\n");
  std::printf("|---|---:|---:|---:|---:|---:|\n");
  for (const Case& c : cases) {
    const auto field = formulaField(model, {"f", c.formula});
    auto t = Clock::now();
    const std::vector<double> viaFormula = field->valuesCopy(0);
    const double formulaMs = msSince(t);
    t = Clock::now();
    const std::vector<double> direct = c.direct(model);
    const double directMs = msSince(t);
    double worst = 0.0;
    for (std::size_t i = 0; i < direct.size(); ++i) worst = std::max(worst, std::abs(direct[i] - viaFormula[i]));
    std::printf("| `%s` | %.0f | %.0f | %.1f | %.0f | %.3g |\n", c.formula, formulaMs, directMs, formulaMs / directMs,
                1e6 * formulaMs / double(viaFormula.size()), worst);
  }
  return 0;
}
