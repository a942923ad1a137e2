// SPDX-License-Identifier: MIT
#include "SetColors.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <map>

namespace volpost::app {
namespace {

// Twelve colors apart in hue and lightness; light enough that the shading and the element
// edges read on them.
constexpr std::array<glm::dvec3, kSetPaletteSize> kPalette{{
    {0.36, 0.58, 0.84},  // blue
    {0.95, 0.56, 0.22},  // orange
    {0.36, 0.71, 0.39},  // green
    {0.85, 0.33, 0.34},  // red
    {0.62, 0.50, 0.80},  // purple
    {0.66, 0.47, 0.36},  // brown
    {0.91, 0.56, 0.78},  // pink
    {0.74, 0.74, 0.27},  // olive
    {0.27, 0.76, 0.80},  // cyan
    {0.99, 0.82, 0.31},  // yellow
    {0.58, 0.77, 0.96},  // light blue
    {0.71, 0.89, 0.55},  // light green
}};

}  // namespace

glm::dvec3 setPaletteColor(std::size_t index) { return kPalette[index % kSetPaletteSize]; }

ColorMap setPaletteMap() {
  // Each color flat over its band (a texture sampled near a band's middle meets only it).
  std::vector<ColorMap::Point> points;
  for (int i = 0; i < kSetPaletteSize; ++i) {
    points.push_back({double(i) / kSetPaletteSize, kPalette[i]});
    points.push_back({(i + 1.0) / kSetPaletteSize - 1e-9, kPalette[i]});
  }
  return ColorMap("element sets", std::move(points));
}

SetColoring setColoring(const ModelSession& drawn, const ModelSession& whole) {
  // A set's color: its place among the whole model's element sets.
  std::map<std::string, std::size_t> place;
  for (const EntitySet& s : modelSets(whole.model()))
    if (s.kind == SetKind::Cells) place.emplace(s.name, place.size());

  const std::vector<EntitySet> sets = modelSets(drawn.model());
  const std::size_t cells = drawn.model().cellCount();
  // Each cell takes the smallest set holding it; of sets the same size, the first.
  constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> owner(cells, none);
  for (std::size_t i = 0; i < sets.size(); ++i) {
    if (sets[i].kind != SetKind::Cells) continue;
    for (const std::uint32_t c : sets[i].members)
      if (c < cells && (owner[c] == none || sets[i].members.size() < sets[owner[c]].members.size())) owner[c] = i;
  }
  SetColoring out;
  std::map<std::size_t, std::size_t> entryOf;  // set index -> entry
  for (std::size_t i = 0; i < sets.size(); ++i) {
    if (sets[i].kind != SetKind::Cells) continue;
    const auto p = place.find(sets[i].name);
    SetColoring::Entry e;
    e.name = sets[i].name;
    e.rgb = setPaletteColor(p != place.end() ? p->second : i);
    entryOf[i] = out.entries.size();
    out.entries.push_back(e);
  }
  std::vector<double> values(cells, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t c = 0; c < cells; ++c) {
    if (owner[c] == none) {
      ++out.cellsInNoSet;
      continue;
    }
    SetColoring::Entry& e = out.entries[entryOf[owner[c]]];
    ++e.cells;
    const auto p = place.find(e.name);
    values[c] = double((p != place.end() ? p->second : owner[c]) % kSetPaletteSize) + 0.5;
  }
  std::erase_if(out.entries, [](const SetColoring::Entry& e) { return e.cells == 0; });
  out.view.location = FieldLocation::Cell;
  out.view.setValues(std::move(values));
  out.view.range.min = 0.0;
  out.view.range.max = double(kSetPaletteSize);
  out.view.range.nanCount = out.cellsInNoSet;
  out.view.range.finiteCount = cells - out.cellsInNoSet;
  return out;
}

}  // namespace volpost::app
