// SPDX-License-Identifier: MIT
#include "DeckSurfaces.hpp"

#include "FaceNodes.hpp"

#include <volpost/core/EntitySet.hpp>

#include <cctype>

namespace volpost::meshio {
namespace {

// Abaqus's face numbering (S1..S6) as the element's own corners, 0-based in the deck's
// node order (Abaqus Analysis User's Guide, solid element faces).
const std::vector<std::vector<int>> kTetFaces{{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
const std::vector<std::vector<int>> kHexFaces{{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1},
                                              {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 4, 0}};
const std::vector<std::vector<int>> kWedgeFaces{{0, 1, 2}, {3, 5, 4}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}};
// The deck's wedge corners in VTK's order swap the 2nd and 3rd of each triangle (its own inverse).
constexpr int kWedgeToVtk[6] = {0, 2, 1, 3, 5, 4};

// The VTK corners of face `face` (1-based) of a cell, or empty where the numbering does
// not apply (a pyramid, a collapsed hexahedron, a number past the element's faces).
std::vector<int> abaqusFace(CellType type, int face, bool collapsed) {
  const std::vector<std::vector<int>>* faces = nullptr;
  const bool wedge = type == CellType::Wedge6 || type == CellType::Wedge15;
  if (type == CellType::Tet4 || type == CellType::Tet10) faces = &kTetFaces;
  else if (type == CellType::Hex8 || type == CellType::Hex20) faces = &kHexFaces;
  else if (wedge && !collapsed) faces = &kWedgeFaces;
  if (!faces || collapsed || face < 1 || std::size_t(face) > faces->size()) return {};
  std::vector<int> corners = (*faces)[std::size_t(face - 1)];
  if (wedge)
    for (int& c : corners) c = kWedgeToVtk[c];
  return corners;
}

bool isNumber(std::string_view f) {
  return !f.empty() && (std::isdigit(static_cast<unsigned char>(f.front())) || f.front() == '-' || f.front() == '+');
}

const EntitySet* setOf(const Model& model, const std::string& name, SetKind kind) {
  for (const EntitySet& s : model.sets)
    if (s.kind == kind && s.origin != "SURFACE" && s.name == name) return &s;
  return nullptr;
}

}  // namespace

void DeckSurfaces::begin(const std::string& name, bool ofNodes) { surfaces_.push_back({name, ofNodes, {}}); }

void DeckSurfaces::readLine(TextScanner& s, std::string_view line) {
  if (surfaces_.empty()) return;
  Written& w = surfaces_.back();
  std::vector<std::string_view> fields;
  for (auto f : splitFields(line, true))
    if (!trim(f).empty()) fields.push_back(trim(f));
  if (fields.empty()) return;
  Entry e;
  if (isNumber(fields[0])) e.id = parseInteger(s, fields[0], w.ofNodes ? "a node id" : "an element id");
  else e.set = toUpper(fields[0]);
  if (!w.ofNodes && fields.size() > 1) {
    const std::string face = toUpper(fields[1]);
    if (face.size() == 2 && face[0] == 'S' && face[1] >= '1' && face[1] <= '6') e.face = face[1] - '0';
    else if (face == "SPOS" || face == "SNEG" || face.rfind("E", 0) == 0) e.face = -1;  // a shell's side or edge
    else s.fail("'" + std::string(fields[1]) + "' is no face of a solid element (S1 to S6)");
  }
  w.entries.push_back(std::move(e));
}

void DeckSurfaces::moveInto(Model& model, const IdIndex& nodes, const IdIndex& elements,
                            const std::unordered_set<std::int64_t>& skipped) const {
  const Mesh& mesh = model.mesh();
  for (const Written& w : surfaces_) {
    EntitySet out{w.name, SetKind::Nodes, "SURFACE", {}};
    std::size_t unknown = 0, unmapped = 0;
    std::string missingSet;
    std::vector<std::uint32_t> freeFacesOf;  // cells named without a face
    const auto addCell = [&](std::uint32_t cell, int face) {
      if (face < 0) return;
      if (face == 0) {
        freeFacesOf.push_back(cell);
        return;
      }
      const std::vector<int> corners = abaqusFace(mesh.cellType(cell), face, collapsed_.count(mesh.cellId(cell)) > 0);
      if (corners.empty()) ++unmapped;
      else appendFaceNodes(mesh, cell, corners, out.members);
    };
    for (const Entry& e : w.entries) {
      if (!e.set.empty()) {
        const EntitySet* s = setOf(model, e.set, w.ofNodes ? SetKind::Nodes : SetKind::Cells);
        if (!s) {
          if (missingSet.empty()) missingSet = e.set;
          continue;
        }
        if (w.ofNodes) out.members.insert(out.members.end(), s->members.begin(), s->members.end());
        else
          for (const std::uint32_t c : s->members) addCell(c, e.face);
      } else if (w.ofNodes) {
        if (const auto n = nodes.find(e.id)) out.members.push_back(*n);
        else ++unknown;
      } else if (const auto c = elements.find(e.id)) {
        addCell(*c, e.face);
      } else if (!skipped.count(e.id)) {
        ++unknown;
      }
    }
    appendFreeFaceNodes(mesh, freeFacesOf, out.members);
    normalizeMembers(out.members);
    const std::string label = "*SURFACE " + w.name;
    if (unknown > 0)
      model.diagnostics.push_back({Severity::Warning,
                                   "set-unknown-ids",
                                   label + " names " + std::to_string(unknown) + " id" + (unknown == 1 ? "" : "s") +
                                       " the deck does not define",
                                   {}});
    if (!missingSet.empty())
      model.diagnostics.push_back({Severity::Warning,
                                   "set-unknown-names",
                                   label + " names " + missingSet + ", which is no set of the deck",
                                   {}});
    if (unmapped > 0)
      model.diagnostics.push_back({Severity::Info,
                                   "surface-faces-skipped",
                                   label + ": " + std::to_string(unmapped) + " face" +
                                       (unmapped == 1 ? " is" : "s are") +
                                       " on pyramids or on hexahedra with repeated nodes, or past the element's faces; "
                                       "their nodes are left out",
                                   {}});
    if (out.members.empty()) {
      model.diagnostics.push_back(
          {Severity::Info, "set-empty", label + " holds no node of the elements volpost loaded", {}});
      continue;
    }
    model.sets.push_back(std::move(out));
  }
}

}  // namespace volpost::meshio
