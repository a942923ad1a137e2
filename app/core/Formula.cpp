// SPDX-License-Identifier: MIT
#include "Formula.hpp"

#include <volpost/core/Quantity.hpp>

#include <muParser.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <deque>
#include <limits>
#include <regex>

namespace volpost::app {
namespace {

// Names may hold "." (S.mises) and "@" (S.mises@2): muParser reads each as one name.
constexpr const char* kNameChars = "0123456789_abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ.@";
constexpr std::size_t kMaxExpressionLength = 4096;
constexpr int kMaxResultValues = 9;

bool isNameChar(char c) { return std::strchr(kNameChars, c) != nullptr && c != '\0'; }

enum class Pin { Shown, Step, Max, Min };
enum class RefKind { Quantity, Components, X, Y, Z, Time };

// One name the expression reads.
struct Reference {
  std::string written;
  RefKind kind = RefKind::Time;
  std::shared_ptr<const Field> field;
  Quantity quantity;
  Pin pin = Pin::Shown;
  std::size_t step = 0;  ///< Pin::Step, 0-based
};

// What the loader needs, fixed when the formula is made: it outlives the model it came from
// (the deformed copy of a model shares its fields).
struct Plan {
  FormulaSpec formula;
  std::vector<Reference> refs;
  FieldLocation location = FieldLocation::Node;
  std::size_t entityCount = 0;
  int resultComponents = 1;
  int componentwise = 0;  ///< >0: evaluated once per component of the whole fields it reads
  std::vector<Step> steps;
  std::shared_ptr<const std::vector<glm::dvec3>> positions;  ///< per entity, when x, y or z is read
  std::shared_ptr<const Mesh> mesh;                          ///< per-cell result of nodal values
};

std::string quoted(const std::string& s) { return "'" + s + "'"; }

[[noreturn]] void fail(const FormulaSpec& f, const std::string& what) {
  throw FormulaError("formula " + quoted(f.name) + ": " + what);
}

// The 0-based position of `name` as a whole name in the expression (npos if not found).
std::size_t positionOf(const std::string& expression, const std::string& name) {
  for (std::size_t at = expression.find(name); at != std::string::npos; at = expression.find(name, at + 1)) {
    const bool startsName = at == 0 || !isNameChar(expression[at - 1]);
    const bool endsName = at + name.size() == expression.size() || !isNameChar(expression[at + name.size()]);
    if (startsName && endsName) return at;
  }
  return std::string::npos;
}

std::string atCharacter(const FormulaSpec& f, std::size_t position) {
  if (position == std::string::npos) return "";
  return " at character " + std::to_string(position + 1) + " of \"" + f.expression + "\"";
}

void configure(mu::Parser& parser) { parser.DefineNameChars(kNameChars); }

// muParser's message without its own 0-based "at position N", which atCharacter says 1-based.
[[noreturn]] void failToParse(const FormulaSpec& f, const mu::Parser::exception_type& e) {
  const std::size_t end = f.expression.find_last_not_of(" \t");
  if (e.GetCode() == mu::ecINTERNAL_ERROR && end != std::string::npos &&
      std::strchr("+-*/^<>=&|?:,!", f.expression[end]))
    fail(f, "the expression ends with '" + std::string(1, f.expression[end]) + "', where a value must follow" +
                atCharacter(f, end));
  static const std::regex position(R"( at (expression )?position \d+)");
  fail(f, std::regex_replace(e.GetMsg(), position, "") +
              atCharacter(f, e.GetPos() < 0 ? std::string::npos : std::size_t(e.GetPos())));
}

// muParser assigns with =, +=, ...: a formula reads the model, it never writes into it.
void checkNoAssignment(const FormulaSpec& f) {
  const std::string& e = f.expression;
  for (std::size_t i = 0; i < e.size(); ++i) {
    if (e[i] != '=') continue;
    const bool compares = (i + 1 < e.size() && e[i + 1] == '=') || (i > 0 && std::strchr("=<>!", e[i - 1]));
    if (compares) {
      if (i + 1 < e.size() && e[i + 1] == '=') ++i;  // the second sign of ==
      continue;
    }
    fail(f, "'=' would assign" + atCharacter(f, i) + "; compare with ==");
  }
}

Pin parsePin(const FormulaSpec& f, const std::string& written, const std::string& text, const Field* field,
             std::size_t& step) {
  const std::size_t at = positionOf(f.expression, written);
  if (text == "max") return Pin::Max;
  if (text == "min") return Pin::Min;
  const std::size_t count = field ? field->stepCount() : 0;
  if (text == "last") {
    step = count ? count - 1 : 0;
    return Pin::Step;
  }
  const bool digits = !text.empty() && text.size() <= 9 && std::all_of(text.begin(), text.end(), ::isdigit);
  if (!digits) fail(f, "after @ in " + quoted(written) + " comes a step number, last, max or min" + atCharacter(f, at));
  const std::size_t k = std::stoul(text);
  if (k < 1 || k > count)
    fail(f, quoted(written) + " asks for step " + text + " of " + field->name() + ", which has " +
                std::to_string(count) + " step" + (count == 1 ? "" : "s") + atCharacter(f, at));
  step = k - 1;
  return Pin::Step;
}

Reference resolve(const Model& model, const FormulaSpec& f, const std::string& written) {
  Reference ref;
  ref.written = written;
  const std::size_t at = written.find('@');
  const std::string base = written.substr(0, at);
  for (const auto& field : model.fields) {
    for (const Quantity& q : quantitiesOf(*field))
      if (formulaName(q.key()) == base) {
        ref.kind = RefKind::Quantity;
        ref.field = field;
        ref.quantity = q;
        break;
      }
    if (!ref.field && field->kind() != FieldKind::Scalar && formulaName(field->name()) == base) {
      ref.kind = RefKind::Components;
      ref.field = field;
    }
    if (ref.field) break;
  }
  if (!ref.field) {
    if (base == "x" || base == "y" || base == "z" || base == "time") {
      ref.kind = base == "x" ? RefKind::X : base == "y" ? RefKind::Y : base == "z" ? RefKind::Z : RefKind::Time;
      if (at != std::string::npos)
        fail(f, quoted(base) + " takes no @ (it is the same at every step)" +
                    atCharacter(f, positionOf(f.expression, written)));
      return ref;
    }
    fail(f, "no quantity or field named " + quoted(base) + atCharacter(f, positionOf(f.expression, written)) +
                "; volpost info lists the model's quantities");
  }
  if (at == std::string::npos) return ref;
  if (written.find('@', at + 1) != std::string::npos)
    fail(f, quoted(written) + " has more than one @" + atCharacter(f, positionOf(f.expression, written)));
  ref.pin = parsePin(f, written, written.substr(at + 1), ref.field.get(), ref.step);
  if (ref.kind == RefKind::Components && (ref.pin == Pin::Max || ref.pin == Pin::Min))
    fail(f, "the envelope " + quoted(written) + " needs a quantity (" + ref.field->name() +
                ".magnitude, a component ...), not a whole " + toString(ref.field->kind()) +
                atCharacter(f, positionOf(f.expression, written)));
  return ref;
}

void checkName(const Model& model, const FormulaSpec& f) {
  static const std::regex valid("[A-Za-z_][A-Za-z0-9_]{0,63}");
  if (!std::regex_match(f.name, valid))
    throw FormulaError("formula name " + quoted(f.name) +
                       ": use a letter or _ first, then letters, digits or _ (at most 64)");
  if (f.name == "x" || f.name == "y" || f.name == "z" || f.name == "time")
    throw FormulaError("formula name " + quoted(f.name) + " is taken by the coordinates and the step's time");
  mu::Parser parser;
  if (parser.GetFunDef().count(f.name) || parser.GetConst().count(f.name))
    throw FormulaError("formula name " + quoted(f.name) + " is taken by a function or constant of formulas");
  for (const auto& field : model.fields)
    if (field->name() == f.name || formulaName(field->name()) == f.name)
      throw FormulaError("formula name " + quoted(f.name) + ": the model already has a field named " +
                         quoted(field->name()));
}

// The steps of the result: those of the fields read at the shown step (a field of one step
// is the same at each); one step when every field read is pinned.
std::vector<Step> resultSteps(const FormulaSpec& f, const std::vector<Reference>& refs) {
  const Field* longest = nullptr;
  for (const Reference& r : refs)
    if (r.field && r.pin == Pin::Shown && (!longest || r.field->stepCount() > longest->stepCount()))
      longest = r.field.get();
  if (!longest) return {Step{"", 0.0}};
  for (const Reference& r : refs)
    if (r.field && r.pin == Pin::Shown && r.field->stepCount() != 1 && r.field->stepCount() != longest->stepCount())
      fail(f, longest->name() + " has " + std::to_string(longest->stepCount()) + " steps and " + r.field->name() + " " +
                  std::to_string(r.field->stepCount()) + "; pin one to a step (" + r.written +
                  "@1) or write both at one step");
  return longest->steps();
}

std::vector<glm::dvec3> entityPositions(const Model& model, FieldLocation location) {
  std::vector<glm::dvec3> out;
  if (location == FieldLocation::Node) {
    out.resize(model.nodeCount());
    for (std::size_t n = 0; n < out.size(); ++n) out[n] = model.nodePosition(n);
    return out;
  }
  const Mesh& mesh = model.mesh();
  out.resize(mesh.cellCount());
  for (std::size_t c = 0; c < out.size(); ++c) {
    glm::dvec3 sum(0.0);
    const auto nodes = mesh.cellNodes(c);
    for (const NodeIndex n : nodes) sum += mesh.nodes[n];
    out[c] = nodes.empty() ? glm::dvec3(std::numeric_limits<double>::quiet_NaN()) : sum / double(nodes.size());
  }
  return out;
}

// Per-node values (components each) as per-cell means over each cell's nodes.
std::vector<double> cellMeans(const Mesh& mesh, const std::vector<double>& nodal, int components) {
  std::vector<double> out(mesh.cellCount() * std::size_t(components), 0.0);
  for (std::size_t c = 0; c < mesh.cellCount(); ++c) {
    const auto nodes = mesh.cellNodes(c);
    for (int k = 0; k < components; ++k) {
      double sum = 0.0;
      for (const NodeIndex n : nodes) sum += nodal[std::size_t(n) * std::size_t(components) + std::size_t(k)];
      out[c * std::size_t(components) + std::size_t(k)] =
          nodes.empty() ? std::numeric_limits<double>::quiet_NaN() : sum / double(nodes.size());
    }
  }
  return out;
}

std::size_t fieldStep(const Reference& r, std::size_t resultStep) {
  if (r.pin == Pin::Step) return r.step;
  return r.field->stepCount() == 1 ? 0 : resultStep;
}

// The envelope of a quantity over every step: a step without a value (NaN) is passed over.
std::vector<double> envelope(const Reference& r) {
  std::vector<double> out = evaluate(*r.field, r.quantity, 0);
  for (std::size_t s = 1; s < r.field->stepCount(); ++s) {
    const std::vector<double> next = evaluate(*r.field, r.quantity, s);
    for (std::size_t i = 0; i < out.size() && i < next.size(); ++i)
      out[i] = r.pin == Pin::Max ? std::fmax(out[i], next[i]) : std::fmin(out[i], next[i]);
  }
  return out;
}

// A reference's values at the result's step, one (or `components`) per result entity.
std::vector<double> referenceValues(const Plan& plan, const Reference& r, std::size_t step) {
  std::vector<double> values;
  int components = 1;
  if (r.kind == RefKind::Quantity)
    values = r.pin == Pin::Max || r.pin == Pin::Min ? envelope(r) : evaluate(*r.field, r.quantity, fieldStep(r, step));
  else {
    values = r.field->valuesCopy(fieldStep(r, step));
    components = r.field->components();
  }
  if (r.field->location() == FieldLocation::Node && plan.location == FieldLocation::Cell)
    values = cellMeans(*plan.mesh, values, components);
  if (values.size() != plan.entityCount * std::size_t(components))
    throw FormulaError("formula " + quoted(plan.formula.name) + ": " + r.field->name() + " holds " +
                       std::to_string(values.size()) + " values where " +
                       std::to_string(plan.entityCount * std::size_t(components)) + " were expected");
  return values;
}

std::vector<double> evaluateStep(const Plan& plan, std::size_t step) {
  std::vector<std::vector<double>> inputs(plan.refs.size());
  for (std::size_t i = 0; i < plan.refs.size(); ++i)
    if (plan.refs[i].field) inputs[i] = referenceValues(plan, plan.refs[i], step);
  std::vector<double> slots(plan.refs.size(), 0.0);
  mu::Parser parser;
  configure(parser);
  for (std::size_t i = 0; i < plan.refs.size(); ++i) parser.DefineVar(plan.refs[i].written, &slots[i]);
  parser.SetExpr(plan.formula.expression);
  const double time = plan.steps[step].time;
  const std::size_t nc = std::size_t(plan.resultComponents);
  std::vector<double> out(plan.entityCount * nc);
  for (std::size_t e = 0; e < plan.entityCount; ++e) {
    const std::size_t perEntity = plan.componentwise ? nc : 1;
    for (std::size_t k = 0; k < perEntity; ++k) {
      for (std::size_t i = 0; i < plan.refs.size(); ++i) {
        const Reference& r = plan.refs[i];
        switch (r.kind) {
          case RefKind::Quantity:
            slots[i] = inputs[i][e];
            break;
          case RefKind::Components:
            slots[i] = inputs[i][e * nc + k];
            break;
          case RefKind::X:
            slots[i] = (*plan.positions)[e].x;
            break;
          case RefKind::Y:
            slots[i] = (*plan.positions)[e].y;
            break;
          case RefKind::Z:
            slots[i] = (*plan.positions)[e].z;
            break;
          case RefKind::Time:
            slots[i] = time;
            break;
        }
      }
      int count = 0;
      const double* result = parser.Eval(count);
      if (plan.componentwise) out[e * nc + k] = result[0];
      else
        for (std::size_t c = 0; c < nc && c < std::size_t(count); ++c) out[e * nc + c] = result[c];
    }
  }
  return out;
}

}  // namespace

FormulaSpec parseFormulaText(const std::string& text) {
  const std::size_t eq = text.find('=');
  auto trim = [](std::string s) {
    const auto first = s.find_first_not_of(" \t"), last = s.find_last_not_of(" \t");
    return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
  };
  if (eq == std::string::npos)
    throw FormulaError("formula " + quoted(text) + ": write NAME=EXPRESSION, such as ratio=S.mises/250");
  FormulaSpec f{trim(text.substr(0, eq)), trim(text.substr(eq + 1))};
  if (f.name.empty() || f.expression.empty())
    throw FormulaError("formula " + quoted(text) + ": write NAME=EXPRESSION, such as ratio=S.mises/250");
  return f;
}

std::string formulaName(const std::string& writtenForm) {
  std::string out = writtenForm;
  for (char& c : out)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.')) c = '_';
  return out;
}

std::vector<std::string> formulaNames(const Model& model) {
  std::vector<std::string> out;
  for (const auto& field : model.fields) {
    if (field->kind() != FieldKind::Scalar) out.push_back(formulaName(field->name()));
    for (const Quantity& q : quantitiesOf(*field)) out.push_back(formulaName(q.key()));
  }
  for (const char* name : {"x", "y", "z", "time"}) out.emplace_back(name);
  return out;
}

std::shared_ptr<Field> formulaField(const Model& model, const FormulaSpec& formula) {
  checkName(model, formula);
  if (formula.expression.find_first_not_of(" \t") == std::string::npos) fail(formula, "the expression is empty");
  if (formula.expression.size() > kMaxExpressionLength)
    fail(formula, "the expression has " + std::to_string(formula.expression.size()) + " characters; at most " +
                      std::to_string(kMaxExpressionLength));
  auto plan = std::make_shared<Plan>();
  plan->formula = formula;
  checkNoAssignment(formula);
  int count = 0;  // values per evaluation: commas separate them
  try {
    // Read with a slot made for every name, so that a syntax error is said as such before
    // the names are looked up.
    std::deque<double> slots;
    mu::Parser parser;
    configure(parser);
    parser.SetVarFactory(
        [](const char*, void* data) {
          auto* store = static_cast<std::deque<double>*>(data);
          store->push_back(1.0);
          return &store->back();
        },
        &slots);
    parser.SetExpr(formula.expression);
    parser.Eval(count);
    for (const auto& [name, unused] : parser.GetUsedVar()) plan->refs.push_back(resolve(model, formula, name));
  } catch (const mu::Parser::exception_type& e) {
    failToParse(formula, e);
  }
  bool perCell = false, needsPositions = false;
  for (const Reference& r : plan->refs) {
    if (r.field && r.field->location() == FieldLocation::Cell) perCell = true;
    if (r.kind == RefKind::X || r.kind == RefKind::Y || r.kind == RefKind::Z) needsPositions = true;
    if (r.kind != RefKind::Components) continue;
    if (plan->componentwise && plan->componentwise != r.field->components())
      fail(formula, "it reads whole fields of " + std::to_string(plan->componentwise) + " and " +
                        std::to_string(r.field->components()) + " components (" + r.written +
                        "); use their quantities (U.x, S.mises ...) instead");
    plan->componentwise = r.field->components();
  }
  plan->location = perCell ? FieldLocation::Cell : FieldLocation::Node;
  plan->entityCount = perCell ? model.cellCount() : model.nodeCount();
  plan->steps = resultSteps(formula, plan->refs);
  if (plan->componentwise && count != 1)
    fail(formula, "a formula over whole vector or tensor fields gives one value per component, not " +
                      std::to_string(count) + "; build a vector from quantities instead (U.x*2, U.y, 0)");
  if (count < 1 || count > kMaxResultValues)
    fail(formula, "it gives " + std::to_string(count) + " values; at most " + std::to_string(kMaxResultValues) +
                      " (1: a scalar, 3: a vector, 6: a symmetric tensor xx, yy, zz, xy, yz, zx)");
  plan->resultComponents = plan->componentwise ? plan->componentwise : count;
  if (needsPositions)
    plan->positions = std::make_shared<const std::vector<glm::dvec3>>(entityPositions(model, plan->location));
  if (perCell) plan->mesh = std::make_shared<const Mesh>(model.mesh());
  const std::size_t entities = plan->entityCount;
  const int components = plan->resultComponents;
  std::vector<Step> steps = plan->steps;
  return std::make_shared<Field>(formula.name, plan->location, components, entities, std::move(steps),
                                 [plan](std::size_t step) { return evaluateStep(*plan, step); });
}

void appendFormulaFields(Model& model, const std::vector<FormulaSpec>& formulas) {
  for (std::size_t i = 0; i < formulas.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j)
      if (formulas[j].name == formulas[i].name)
        throw FormulaError("two formulas are named " + quoted(formulas[i].name));
    model.fields.push_back(formulaField(model, formulas[i]));
  }
}

}  // namespace volpost::app
