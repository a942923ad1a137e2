// SPDX-License-Identifier: MIT
// The scene as state: it compiles without GL (the command-line verbs and panels use it
// without a context) and counts each kind of change, so a drawing uploads only what
// changed.
#include "core/Scene.hpp"

#if defined(EPOXY_GL_H) || defined(__gl_h_)
#error "Scene.hpp brings in OpenGL: the scene's state must compile without it (SceneDrawing draws it)"
#endif

#include "support/BarSession.hpp"
#include "support/ReaderSupport.hpp"
#include "support/TestSupport.hpp"

using namespace volpost;
using namespace volpost::app;

namespace {

using volpost::test::barSession;

// Which counts moved between two snapshots, by name: "planes", "colorMap tables".
std::string moved(const SceneRevisions& a, const SceneRevisions& b) {
  std::string out;
  const auto check = [&](const char* name, std::uint64_t x, std::uint64_t y) {
    if (x != y) out += (out.empty() ? "" : " ") + std::string(name);
  };
  check("model", a.model, b.model);
  check("scalars", a.scalars, b.scalars);
  check("colorMap", a.colorMap, b.colorMap);
  check("renderer", a.renderer, b.renderer);
  check("geometry", a.geometry, b.geometry);
  check("values", a.values, b.values);
  check("tables", a.tables, b.tables);
  check("planes", a.planes, b.planes);
  check("iso", a.iso, b.iso);
  check("mode", a.mode, b.mode);
  check("streamlines", a.streamlines, b.streamlines);
  return out;
}

}  // namespace

// Each setter counts what it changes and nothing else: a dragged plane is a plane.
TEST(SceneChanges, EachSetterCountsOnlyWhatItChanges) {
  Scene scene{VolumeRendererFactory{}};
  scene.setSession(barSession());
  scene.setResult("S.mises", 0);
  const auto after = [&](const std::function<void()>& change) {
    const SceneRevisions before = scene.revisions();
    change();
    return moved(before, scene.revisions());
  };
  EXPECT_EQ(after([&] { scene.setClipPlanes({{{5.0, 0.5, 0.5}, {1, 0, 0}}}); }), "planes");
  EXPECT_EQ(after([&] { scene.setIsoSurfaces({{1.0, {1, 0, 0}, 1.0}}); }), "iso");
  EXPECT_EQ(after([&] { scene.setTermination(0.01); }), "mode");
  EXPECT_EQ(after([&] { scene.setResult("S.xx", 0); }), "scalars values tables")
      << "other values at the same nodes, and the default transfer function follows their range";
  EXPECT_EQ(after([&] { scene.setTransferFunction(scene.transferFunction()); }), "tables");
  EXPECT_EQ(after([&] { scene.setResult("S.mises", 0); }), "scalars values")
      << "a transfer function of the user's own stays as it is";
  EXPECT_EQ(after([&] { scene.setColorMap("viridis"); }), "colorMap streamlines");
  EXPECT_EQ(after([&] { scene.setShowLegend(false); }), "") << "the legend is painted over the picture";
  EXPECT_EQ(after([&] { scene.setSession(barSession()); }),
            "model scalars colorMap renderer geometry values tables planes iso mode streamlines");
}

// Two scenes never share their counts: a drawing tells them apart.
TEST(SceneChanges, EveryScenesCountsAreItsOwn) {
  const Scene a{VolumeRendererFactory{}}, b{VolumeRendererFactory{}};
  EXPECT_NE(a.revisions().scene, b.revisions().scene);
}
