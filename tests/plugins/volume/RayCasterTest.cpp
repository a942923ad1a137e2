// SPDX-License-Identifier: MIT
// The GPU ray caster (headless EGL) against the exact CPU reference renderer, with stated
// error bounds per integration mode, and the hard cases: no pixel lost on axis-aligned
// views of a tetrahedralized grid, clip planes, element results, a far-away tiny mesh.
#include "VolumeImageFixture.hpp"

#include "TetMeshGpu.hpp"

#include <algorithm>
#include <random>

using namespace volpost;
using namespace volpost::test;

TEST_F(RayCast, LinearSegmentsMatchTheReference) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  const ImageError e = againstReference(grid, FieldLocation::Node, field(grid), kTf, isoCamera(grid), 64);
  std::printf("raycast linear-segments vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 1e-5);  // float32 and the 512^2 psi table are all that is left
  EXPECT_LE(e.max, 1e-4);
}

TEST_F(RayCast, PreIntegratedAndSamplingAreBoundedToo) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  caster_->setIntegrationMode(IntegrationMode::LinearSegmentsIsoTable);
  const ImageError iso = againstReference(grid, FieldLocation::Node, field(grid), kTf, isoCamera(grid), 64);
  std::printf("raycast linear segments, iso-detection table 256^2 vs reference: RMSE %.3g, max %.3g\n", iso.rmse, iso.max);
  EXPECT_LE(iso.rmse, 1e-5);  // measured 2.6e-7: the table only says where to cut, never wrongly
  EXPECT_LE(iso.max, 1e-4);
  caster_->setIntegrationMode(IntegrationMode::PreIntegrated);
  const ImageError pre = againstReference(grid, FieldLocation::Node, field(grid), kTf, isoCamera(grid), 64);
  std::printf("raycast pre-integrated 256^2 x 9 vs reference: RMSE %.3g, max %.3g\n", pre.rmse, pre.max);
  EXPECT_LE(pre.rmse, 2e-5);  // measured 2.6e-6 and 7.9e-5: exact opacity, the table's color
  EXPECT_LE(pre.max, 5e-4);
  caster_->setIntegrationMode(IntegrationMode::Sampling);
  caster_->setSamplingStep(0.05);
  const ImageError sampled = againstReference(grid, FieldLocation::Node, field(grid), kTf, isoCamera(grid), 64);
  std::printf("raycast sampling step 0.05 vs reference: RMSE %.3g, max %.3g\n", sampled.rmse, sampled.max);
  EXPECT_LE(sampled.rmse, 2e-4);  // a midpoint rule at 1/20 of the cell size
  EXPECT_LE(sampled.max, 2e-3);
}

// A wave seen through an opacity peak 3 % of the range wide: tables over the values lose
// such a peak between their texels (the "netting" of tet faces) unless they are built for it.
TEST_F(RayCast, ASharpPeakIsNotNettedByTheTables) {
  const Mesh grid = test::tetGrid(8, 8, 8);
  std::vector<double> wave;
  for (const auto& p : grid.nodes) wave.push_back(std::sin(0.75 * p.x) * std::cos(0.6 * p.y) + 0.5 * std::sin(0.9 * p.z));
  const auto [lo, hi] = std::minmax_element(wave.begin(), wave.end());
  const double mid = *lo + 0.6 * (*hi - *lo), half = 0.015 * (*hi - *lo), tau = 60.0 / std::sqrt(3.0 * 64.0);
  const TransferFunction peak({{*lo, {0.2, 0.3, 0.9}, 0.0}, {mid - half, {0.2, 0.3, 0.9}, 0.0},
                               {mid, {1.0, 0.6, 0.1}, tau}, {mid + half, {0.9, 0.2, 0.1}, 0.0}, {*hi, {0.9, 0.2, 0.1}, 0.0}});
  for (IntegrationMode mode :
       {IntegrationMode::LinearSegments, IntegrationMode::PreIntegrated, IntegrationMode::LinearSegmentsIsoTable}) {
    caster_->setIntegrationMode(mode);
    const ImageError e = againstReference(grid, FieldLocation::Node, wave, peak, isoCamera(grid), 96);
    std::printf("raycast %s through a sharp peak vs reference: RMSE %.3g, max %.3g\n", std::string(toString(mode)).c_str(),
                e.rmse, e.max);
    EXPECT_LE(e.rmse, 5e-5);  // measured 1.0e-6, 4.1e-6 (pre-integrated), 1.0e-6
    EXPECT_LE(e.max, 1e-3);   // 4.0e-5, 1.0e-4, 4.0e-5; before: iso-table 0.68, pre-integrated 0.067 on the bench
  }
}

// Functions a table handles badly: a step (two control points at one value), a single
// point (constant), and one transparent everywhere.
TEST_F(RayCast, TableModesHandleStepsSinglePointsAndEmptyFunctions) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  const TransferFunction step({{0.0, {0.2, 0.3, 0.9}, 0.0}, {3.0, {0.2, 0.3, 0.9}, 0.1}, {3.0, {1.0, 0.5, 0.1}, 1.5},
                               {6.0, {0.9, 0.1, 0.1}, 0.8}});
  const TransferFunction single({{2.0, {0.4, 0.8, 0.2}, 0.7}});
  const TransferFunction clear({{0.0, {1, 1, 1}, 0.0}, {6.0, {1, 0, 0}, 0.0}});
  for (IntegrationMode mode :
       {IntegrationMode::LinearSegments, IntegrationMode::PreIntegrated, IntegrationMode::LinearSegmentsIsoTable}) {
    caster_->setIntegrationMode(mode);
    for (const TransferFunction* tf : {&step, &single, &clear}) {
      const char* name = tf == &step ? "step" : tf == &single ? "single point" : "transparent";
      const ImageError e = againstReference(grid, FieldLocation::Node, field(grid), *tf, isoCamera(grid), 48);
      std::printf("raycast %s, %s function vs reference: RMSE %.3g, max %.3g\n", std::string(toString(mode)).c_str(), name,
                  e.rmse, e.max);
      // The pre-integrated table blurs a step over one value texel: its colour only.
      const bool blurred = mode == IntegrationMode::PreIntegrated && tf == &step;
      EXPECT_LE(e.rmse, blurred ? 2e-4 : 1e-5) << toString(mode) << ", " << name;
      EXPECT_LE(e.max, blurred ? 5e-3 : 1e-4) << toString(mode) << ", " << name;
    }
  }
}

// Thousands of control points with a step among them (a colour map with a hard edge): a
// frame finishes and matches the reference in the exact modes. A NaN in a ray's
// transmittance once left it unfinished for ever and the host dispatching without end.
TEST_F(RayCast, ThousandsOfPointsWithAStepFinishAndMatchTheReference) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  std::vector<ControlPoint> points;
  for (int i = 0; i < 3000; ++i) {
    const double v = 6.0 * i / 2999.0;
    points.push_back({v, {double(i % 2), 0.5, double(1 - i % 2)}, 0.1 * (i % 5)});
  }
  points.push_back({points[1500].value, {1.0, 1.0, 0.0}, 1.5});
  const TransferFunction many(points);
  for (IntegrationMode mode : {IntegrationMode::LinearSegments, IntegrationMode::LinearSegmentsIsoTable}) {
    caster_->setIntegrationMode(mode);
    const ImageError e = againstReference(grid, FieldLocation::Node, field(grid), many, isoCamera(grid), 96);
    std::printf("raycast %s, 3001 points with a step vs reference: RMSE %.3g, max %.3g\n",
                std::string(toString(mode)).c_str(), e.rmse, e.max);
    EXPECT_LE(e.rmse, 5e-5);  // measured 1.2e-5 / 6.6e-5 (float over ~6000 pieces a ray); before: 0.013 / 0.19
    EXPECT_LE(e.max, 1e-3);
  }
}

TEST_F(RayCast, NoPixelIsLostOnAxisAlignedAndDiagonalViewsOfATetrahedralizedGrid) {
  const int lost = lostPixelsOnDegenerateViews();
  EXPECT_EQ(lost, 0);
}

TEST_F(RayCast, ClipPlanesCutLikeTheReference) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  const std::vector<ClipPlane> clips = {{{0, 0, 1.3}, {0, 0.2, 1}}, {{2.5, 0, 0}, {-1, 0, 0}}};
  const ImageError e = againstReference(grid, FieldLocation::Node, field(grid), kTf, isoCamera(grid), 64, clips);
  std::printf("raycast with 2 clip planes vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 1e-5);
  EXPECT_LE(e.max, 1e-4);
}

TEST_F(RayCast, ElementResultsAreConstantPerCell) {
  const Mesh grid = test::tetGrid(3, 3, 3);
  std::vector<double> cells(grid.cellCount());
  for (std::size_t c = 0; c < cells.size(); ++c) cells[c] = double(c % 7);
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  const ImageError e = againstReference(grid, FieldLocation::Cell, cells, kTf, isoCamera(grid), 48);
  std::printf("raycast element results vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 1e-5);
  EXPECT_LE(e.max, 1e-4);
}

TEST_F(RayCast, FarFromOriginTinyMeshRendersLikeTheReference) {
  const glm::dvec3 offset(1048576.0, -1048576.0, 2097152.0);
  const double cell = 1.0 / 1024.0;
  const Mesh grid = test::tetGrid(4, 4, 4, offset, cell);
  std::vector<double> values;
  for (const auto& p : grid.nodes) values.push_back((p.x - offset.x) / cell + 0.5 * (p.z - offset.z) / cell);
  std::vector<ControlPoint> scaled = kTf.points();
  for (auto& p : scaled) p.extinction /= cell;
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  const ImageError e = againstReference(grid, FieldLocation::Node, values, TransferFunction(scaled), isoCamera(grid), 48);
  std::printf("raycast mesh at 1e6 with 1e-3 cells vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 1e-5);
  EXPECT_LE(e.max, 1e-4);
}

TEST_F(RayCast, TinyAndOffsetValuesRenderLikeTheReference) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  expectValueScaleInvariance("raycast", [&](const std::vector<double>& values, const TransferFunction& tf) {
    return againstReference(grid, FieldLocation::Node, values, tf, isoCamera(grid), 64);
  });
}

TEST_F(RayCast, ExtremeExtinctionsRenderLikeTheReference) { expectExtremeExtinctionsLikeTheReference("raycast"); }

TEST_F(RayCast, AnOpaqueRampAfterAClearRangeRendersLikeTheReference) { expectAnOpaqueRampLikeTheReference("raycast"); }

TEST_F(RayCast, TransferFunctionEditsDoNotTouchTheMesh) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  caster_->setVolume(grid, FieldLocation::Node, field(grid));
  (void)gpuImage(isoCamera(grid), 16, 16);
  const VolumeStats before = caster_->stats();
  caster_->setTransferFunction(kTf);
  (void)gpuImage(isoCamera(grid), 16, 16);
  const VolumeStats after = caster_->stats();
  EXPECT_EQ(after.meshBytes, before.meshBytes);
  EXPECT_EQ(after.meshUploads, before.meshUploads);
  EXPECT_EQ(after.valueUploads, before.valueUploads);
  EXPECT_EQ(after.tableBuilds, before.tableBuilds + 1);
  // 28 B per tet (vertex ids 16, packed neighbours 12) + 16 B per node + the boundary BVH;
  // this small grid has many boundary faces per tet (the scale bench: 31.4 B/tet at 12.6M).
  EXPECT_LT(double(before.meshBytes) / double(grid.cellCount()), 52.0);
  EXPECT_GT(after.lastTransferFunctionMs, 0.0);
  EXPECT_EQ(after.tetrahedra, grid.cellCount());
}

// Setters only record: a frame uploads what changed since the last one, once. Moving a
// clip plane or an iso-surface, or setting the same function again, costs only the frame.
TEST_F(RayCast, SettersRecordAndTheFrameUploadsOnlyWhatChanged) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  caster_->setVolume(grid, FieldLocation::Node, field(grid));
  caster_->setTransferFunction(kTf);
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  EXPECT_EQ(caster_->stats().meshUploads, 0u) << "setters make no GL call";
  (void)gpuImage(isoCamera(grid), 16, 16);
  const VolumeStats first = caster_->stats();
  EXPECT_EQ(first.meshUploads, 1u);
  EXPECT_EQ(first.tableBuilds, 1u);
  for (int i = 0; i < 5; ++i) {  // a drag: plane and iso-surface move every event
    caster_->setClipPlanes({{{1.0 + 0.3 * i, 0, 0}, {1, 0, 0}}});
    caster_->setIsoSurfaces({{2.0 + 0.1 * i, {1, 1, 1}, 0.5}});
    caster_->setTransferFunction(kTf);
    (void)gpuImage(isoCamera(grid), 16, 16);
  }
  const VolumeStats dragged = caster_->stats();
  EXPECT_EQ(dragged.meshUploads, first.meshUploads);
  EXPECT_EQ(dragged.valueUploads, first.valueUploads);
  EXPECT_EQ(dragged.tableBuilds, first.tableBuilds);
  std::vector<double> other = field(grid);
  for (double& v : other) v *= 0.5;
  caster_->setValues(other);
  caster_->setValues(other);
  (void)gpuImage(isoCamera(grid), 16, 16);
  EXPECT_EQ(caster_->stats().valueUploads, first.valueUploads + 1) << "two value changes, one upload";
  EXPECT_EQ(caster_->stats().meshUploads, first.meshUploads);
}

TEST_F(RayCast, LimitsAreStatedAndEnforced) {
  std::vector<ClipPlane> planes(std::size_t(kMaxClipPlanes), ClipPlane{{0, 0, 0}, {1, 0, 0}});
  EXPECT_NO_THROW(caster_->setClipPlanes(planes));
  planes.push_back(planes.front());
  EXPECT_THROW(caster_->setClipPlanes(planes), std::invalid_argument);
  EXPECT_THROW(caster_->setClipPlanes({{{0, 0, 0}, {0, 0, 0}}}), std::invalid_argument);
  EXPECT_THROW(caster_->setClipPlanes({{{0, 0, 0}, {std::nan(""), 0, 1}}}), std::invalid_argument);
  EXPECT_NO_THROW(caster_->setClipPlanes({{{0, 0, 0}, {1e308, 1e308, 0}}})) << "normalized without overflow";
  std::vector<optics::IsoSurface> isos(std::size_t(kMaxIsoSurfaces) + 1, optics::IsoSurface{1.0, {1, 1, 1}, 1.0});
  EXPECT_THROW(caster_->setIsoSurfaces(isos), std::invalid_argument);
  EXPECT_THROW(caster_->setIsoSurfaces({{1.0, {1, 1, 1}, std::nan("")}}), std::invalid_argument);
}

TEST_F(RayCast, EveryVolumeShaderCompilesInEveryMode) {
  for (IntegrationMode mode : allIntegrationModes()) {
    caster_->setIntegrationMode(mode);
    auto& volume = static_cast<volume::TetVolumeRenderer&>(*caster_).volume();
    EXPECT_NO_THROW(volume.program({"volume/raycast.comp"})) << toString(mode);
    EXPECT_NO_THROW(volume.program({"volume/vicp.vert", "volume/vicp.frag"})) << toString(mode);
  }
}

TEST_F(RayCast, AsynchronousPreIntegrationCatchesUpWithTheLatestFunction) {
  // Interactive use: the pre-integrated table is built off the GL thread, frames keep the
  // previous one, rapid changes coalesce; once it is in, the picture is the synchronous one.
  const Mesh grid = test::tetGrid(4, 4, 4);
  const Camera camera = isoCamera(grid);
  caster_->setVolume(grid, FieldLocation::Node, field(grid));
  caster_->setIntegrationMode(IntegrationMode::PreIntegrated);
  caster_->setTerminationThreshold(0.0);
  TransferFunction other = kTf;
  std::vector<ControlPoint> points = kTf.points();
  for (auto& p : points) p.extinction *= 3.0;
  other = TransferFunction(points);
  caster_->setTransferFunction(other);
  const std::vector<float> synchronous = gpuImage(camera, 48, 48);
  caster_->setTransferFunction(kTf);
  caster_->setAsynchronousUpdates(true);
  for (int i = 0; i < 5; ++i) {  // a drag, a frame per event (none waits); it ends on `other`
    caster_->setTransferFunction(i % 2 ? kTf : other);
    (void)gpuImage(camera, 48, 48);
  }
  EXPECT_TRUE(caster_->hasPendingWork());
  for (int i = 0; i < 2000 && caster_->hasPendingWork(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    (void)gpuImage(camera, 48, 48);
  }
  ASSERT_FALSE(caster_->hasPendingWork());
  EXPECT_EQ(gpuImage(camera, 48, 48), synchronous);
  EXPECT_GT(caster_->stats().lastTransferFunctionMs, 0.0);
}

TEST_F(RayCast, RaysReenterANonConvexMeshLikeTheReference) {
  const Mesh m = test::threeSlabs();  // every ray along z enters three times
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  const ImageError e = againstReference(m, FieldLocation::Node, field(m), kTf, isoCamera(m), 48);
  std::printf("raycast non-convex (3 slabs) vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 2e-3);
  EXPECT_LE(e.max, 1e-2);
}

// The entry maps (each pixel's nearest and farthest entry, drawn before the frame with the
// entry search's own test) change nothing but the speed: the same picture bit for bit as
// searching the BVH for every entry, on a convex grid, on a mesh every ray enters three
// times, with a clip plane, through a part of the mesh (hidden tets skipped), orthographic
// and perspective, and from inside the mesh's bounding box.
TEST_F(RayCast, EntryMapsChangeNothingButTheSpeed) {
  auto& caster = dynamic_cast<volume::RayCaster&>(*caster_);
  const Mesh slabs = test::threeSlabs();  // every ray along z enters three times
  const Mesh grid = test::tetGrid(6, 6, 6);
  const TransferFunction peak({{0.0, {0.2, 0.3, 0.9}, 0.0}, {4.0, {0.2, 0.3, 0.9}, 0.0}, {4.2, {1.0, 0.6, 0.1}, 3.0},
                               {4.4, {0.9, 0.2, 0.1}, 0.0}, {9.0, {0.9, 0.2, 0.1}, 0.0}});
  struct Case {
    const Mesh* mesh;
    const TransferFunction* tf;
    std::vector<ClipPlane> clips;
    const char* what;
  };
  const std::vector<Case> cases = {{&grid, &kTf, {}, "convex grid"},
                                   {&slabs, &kTf, {}, "three slabs"},
                                   {&grid, &kTf, {{{3.0, 3.0, 3.0}, glm::normalize(glm::dvec3(1.0, -0.4, 0.2))}}, "clip plane"},
                                   {&grid, &peak, {}, "narrow peak (a part of the mesh)"}};
  caster_->setTerminationThreshold(0.0);
  for (const Case& c : cases) {
    caster_->setVolume(*c.mesh, FieldLocation::Node, field(*c.mesh));
    caster_->setTransferFunction(*c.tf);
    caster_->setClipPlanes(c.clips);
    Camera ortho = isoCamera(*c.mesh), near = isoCamera(*c.mesh), axis;
    ortho.setProjection(Camera::Projection::Orthographic);
    near.zoom(3.0);  // the eye inside the mesh's bounding box
    axis.setView(StandardView::PlusX);
    axis.fit(c.mesh->bounds());
    for (const Camera& camera : {isoCamera(*c.mesh), ortho, near, axis}) {
      caster.setEntryMaps(true);
      const auto mapped = gpuImage(camera, 56, 48);
      EXPECT_TRUE(caster.lastFrame().entryMaps) << c.what;
      caster.setEntryMaps(false);
      const auto searched = gpuImage(camera, 56, 48);
      EXPECT_FALSE(caster.lastFrame().entryMaps);
      float alpha = 0.0f;
      for (std::size_t i = 3; i < mapped.size(); i += 4) alpha = std::max(alpha, mapped[i]);
      EXPECT_GT(alpha, 0.01f) << c.what << ": something shows";
      EXPECT_EQ(mapped, searched) << c.what;
    }
  }
  caster.setEntryMaps(true);
  // A picture with fewer than two pixels per face (a quick frame of a big mesh): searched.
  caster_->setVolume(grid, FieldLocation::Node, field(grid));
  caster_->setTransferFunction(kTf);
  caster_->setClipPlanes({});
  (void)gpuImage(isoCamera(grid), 24, 16);
  EXPECT_FALSE(caster.lastFrame().entryMaps) << "384 pixels, 432 faces";
}

TEST_F(RayCast, ANewResultUploadsOnlyValues) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  std::vector<double> other;
  for (const auto& p : grid.nodes) other.push_back(4.0 - p.y + 0.3 * p.x);
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  caster_->setTerminationThreshold(0.0);
  caster_->setTransferFunction(kTf);
  caster_->setVolume(grid, FieldLocation::Node, field(grid));
  caster_->setValues(other);
  const auto updated = gpuImage(isoCamera(grid), 40, 40);
  caster_->setVolume(grid, FieldLocation::Node, other);
  const auto rebuilt = gpuImage(isoCamera(grid), 40, 40);
  EXPECT_EQ(updated, rebuilt);
  volume::TetMeshGpu gpu = volume::buildTetMeshGpu(grid, FieldLocation::Node, field(grid));
  const auto bvh = gpu.bvh;
  EXPECT_TRUE(volume::replaceValues(gpu, grid, FieldLocation::Node, other));
  EXPECT_EQ(gpu.bvh, bvh);
  EXPECT_FLOAT_EQ(gpu.nodes[7].w, gpu.gpuValue(other[7]));
  other[3] = std::nan("");  // a tet would drop out: the structure must be rebuilt
  EXPECT_FALSE(volume::replaceValues(gpu, grid, FieldLocation::Node, other));
}

// Once on the GPU, the tets and their neighbours are not kept in host memory a second time
// (32 bytes per tet); the frames after that draw the same, and a renderer released and
// initialized again says the volume must be set again instead of drawing nothing silently.
TEST_F(RayCast, TheTetsLiveOnlyOnTheGpuOnceUploaded) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  volume::RayCaster caster;
  caster.initialize();
  caster.setTransferFunction(kTf);
  caster.setVolume(grid, FieldLocation::Node, field(grid));
  const VolumeStats before = caster.stats();
  const auto first = imageOf(caster, isoCamera(grid), 32, 32);
  const auto second = imageOf(caster, isoCamera(grid), 32, 32);
  EXPECT_EQ(first, second);
  EXPECT_EQ(caster.stats().tetrahedra, grid.cellCount());
  EXPECT_EQ(caster.stats().meshBytes, before.meshBytes) << "the GPU's bytes are still counted";
  std::vector<double> other = field(grid);
  for (double& v : other) v = 5.0 - v;
  caster.setValues(other);  // only the values travel: the tets are not needed on the host
  EXPECT_NE(imageOf(caster, isoCamera(grid), 32, 32), first);
  caster.release();
  caster.initialize();
  caster.setTransferFunction(kTf);
  try {
    (void)imageOf(caster, isoCamera(grid), 32, 32);
    ADD_FAILURE() << "drew without its tetrahedra";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("set the volume again"), std::string::npos) << e.what();
  }
  caster.setVolume(grid, FieldLocation::Node, field(grid));
  EXPECT_EQ(imageOf(caster, isoCamera(grid), 32, 32), first);
  caster.release();
}

TEST_F(RayCast, IsoSurfacesMatchTheReference) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  const std::vector<optics::IsoSurface> isos = {{1.7, {0.9, 0.8, 0.1}, 0.6}, {3.9, {0.1, 0.7, 0.9}, 1.0}};
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  caster_->setIsoSurfaces(isos);
  caster_->setVolume(grid, FieldLocation::Node, field(grid));
  caster_->setTransferFunction(kTf);
  caster_->setTerminationThreshold(0.0);
  const Camera camera = isoCamera(grid);
  const auto gpu = gpuImage(camera, 64, 64);
  const optics::TetVolume volume(grid, FieldLocation::Node, field(grid));
  optics::RaySettings settings;
  settings.isoSurfaces = isos;
  const ImageError e = compare(gpu, optics::renderReference(volume, kTf, camera, 64, 64, settings));
  std::printf("raycast with 2 iso-surfaces vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 1e-4);
  EXPECT_LE(e.max, 5e-3);
}

// An iso-surface on inner faces: the walk hands the value on from tet to tet.
TEST_F(RayCast, AnIsoSurfaceOnInnerFacesIsDrawnOnce) { expectIsoSurfaceOnInnerFacesDrawnOnce("raycast"); }

TEST_F(RayCast, OpaqueGeometryEndsRaysAtItsDepth) {
  const ImageError e = opaqueDepthAgainstReference();
  std::printf("raycast ended by scene depth vs reference clipped there: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 1e-4);
  EXPECT_LE(e.max, 5e-3);
}

TEST_F(RayCast, NoRayIsLostOnTheRealWheel) {
  // Regression: at 256 px one ray of the gmsh wheel entered a boundary tet exactly at an
  // edge shared with another boundary face, left through it with no length, and kept
  // re-entering through the same face; the rest of its path was lost.
  VOLPOST_SHARED_OR_SKIP(path, "wheel/tet4/wheel_tet4.vtu");
  const auto model = test::meshioReaders().load(path);
  const Field& s = *model->findField("S_Mises");
  std::vector<double> values = s.values(0);
  const TransferFunction tf = TransferFunction::ramp(0.0, 40.0, "cool-warm", 0.08, 11);
  Camera camera;
  camera.setView(StandardView::Isometric);
  camera.fit(model->mesh().bounds());
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  const ImageError e = againstReference(model->mesh(), FieldLocation::Node, values, tf, camera, 256);
  std::printf("raycast real wheel 256 px vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.max, 1e-3);
}


// ---- frames in several dispatches --------------------------------------------------------

namespace {

volume::RayCaster& rayCaster(VolumeRenderer& r) { return dynamic_cast<volume::RayCaster&>(r); }

}  // namespace

TEST_F(RayCast, ARayThroughTensOfThousandsOfTetsIsResumedAcrossDispatchesExactly) {
  // A column of 24000 unit cubes seen end on: each ray crosses 3 tets per cube, 72000 in
  // all, more than one dispatch takes (32768) and more than the 65535 loop iterations
  // llvmpipe documents as its limit. Resumed twice, every pixel must still be
  // 1 - exp(-tau L) = 0.909, L the column's length (a ray stopped at 65535 tets: 0.887),
  // within the float rounding of 72000 transmittance factors (each exp(-3.3e-5) is
  // rounded to 6e-8 of 1).
  const int cubes = 24000;
  const Mesh column = test::tetGrid(1, 1, cubes);
  const double tau = 1e-4;
  const TransferFunction tf({{0.0, {1.0, 1.0, 1.0}, tau}, {1.0, {1.0, 1.0, 1.0}, tau}});
  caster_->setVolume(column, FieldLocation::Node, std::vector<double>(column.nodeCount(), 0.5));
  caster_->setTransferFunction(tf);
  caster_->setTerminationThreshold(0.0);
  Camera camera;
  camera.fit(column.bounds());
  camera.setProjection(Camera::Projection::Orthographic);
  const double middle = 0.5 * cubes;
  camera.lookAt({0.5, 0.5, middle + 1.5}, {0.5, 0.5, middle}, {0.0, 1.0, 0.0});  // a view 0.8 wide
  const std::vector<float> image = gpuImage(camera, 8, 8);
  const double expected = 1.0 - std::exp(-tau * cubes);
  for (std::size_t i = 0; i < 64; ++i) ASSERT_NEAR(image[4 * i + 3], expected, 2e-3) << "pixel " << i;
  EXPECT_GE(rayCaster(*caster_).lastFrame().dispatches, 3) << "72000 tets at 32768 per dispatch";
  EXPECT_EQ(rayCaster(*caster_).lastFrame().cappedRays, 0u);
}

TEST_F(RayCast, AFrameInManyShortDispatchesAndBandsIsTheSameImage) {
  // Resumed rays go on with the very numbers they stopped with: a frame taken 7 tets per
  // dispatch, 5 rows of rays at a time (as on a device whose storage blocks hold little),
  // equals the frame taken at once, bit for bit, in every mode, with clip planes and
  // iso-surfaces.
  const Mesh grid = test::tetGrid(4, 4, 4);
  const Camera camera = isoCamera(grid);
  caster_->setVolume(grid, FieldLocation::Node, field(grid));
  caster_->setTransferFunction(kTf);
  caster_->setClipPlanes({{{2.0, 2.0, 2.0}, {0.3, -1.0, 0.2}}});
  caster_->setIsoSurfaces({{3.0, {1.0, 0.8, 0.2}, 0.5}});
  for (IntegrationMode mode :
       {IntegrationMode::LinearSegments, IntegrationMode::PreIntegrated, IntegrationMode::LinearSegmentsIsoTable}) {
    caster_->setIntegrationMode(mode);
    auto& caster = rayCaster(*caster_);
    caster.setStepsPerPass(volume::RayCaster::kStepsPerPass);
    caster.setBandRowsLimit(0);
    const std::vector<float> whole = gpuImage(camera, 48, 48);
    EXPECT_EQ(caster.lastFrame().dispatches, 1);
    caster.setStepsPerPass(7);
    caster.setBandRowsLimit(5);
    const std::vector<float> sliced = gpuImage(camera, 48, 48);
    EXPECT_GT(caster.lastFrame().dispatches, 10);  // 10 bands, several dispatches each
    EXPECT_EQ(sliced, whole) << toString(mode);
  }
}

TEST_F(RayCast, TheWindowGetsAQuickFrameAndTheFullOneInSlicesThatEqualsTheSynchronousFrame) {
  const Mesh grid = test::tetGrid(5, 4, 3);
  Camera camera = isoCamera(grid);
  caster_->setVolume(grid, FieldLocation::Node, field(grid));
  caster_->setTransferFunction(kTf);
  caster_->setTerminationThreshold(0.0);
  const std::vector<float> synchronous = gpuImage(camera, 64, 48);
  auto& caster = rayCaster(*caster_);
  caster.setAsynchronousUpdates(true);
  caster.setFrameBudget(1e-3, 1e-3);  // as if every frame were slow: the smallest slices
  caster.setStepsPerPass(4);
  (void)gpuImage(camera, 64, 48);
  EXPECT_GT(caster.shownReduction(), 1) << "a quick frame first";
  EXPECT_TRUE(caster.hasPendingWork()) << "the full frame is still to come";
  int calls = 1;
  for (; calls < 10000 && caster.hasPendingWork(); ++calls) (void)gpuImage(camera, 64, 48);
  ASSERT_FALSE(caster.hasPendingWork());
  EXPECT_GT(calls, 2) << "the full frame took several calls";
  // Bands sized to the slice: one band of the whole picture held the window 4 s on a post.
  EXPECT_GT(caster.lastFrame().refinedBands, 4) << "the picture refined in bands of a few rows";
  EXPECT_EQ(caster.shownReduction(), 1);
  EXPECT_EQ(gpuImage(camera, 64, 48), synchronous) << "the refined frame is the synchronous one";
  // Another view starts over with a quick frame; so does a changed transfer function.
  camera.orbit(10.0, 0.0);
  (void)gpuImage(camera, 64, 48);
  EXPECT_TRUE(caster.hasPendingWork());
  for (int i = 0; i < 10000 && caster.hasPendingWork(); ++i) (void)gpuImage(camera, 64, 48);
  caster.setTransferFunction(TransferFunction::ramp(0.0, 6.0, "cool-warm", 0.3, 5));
  (void)gpuImage(camera, 64, 48);
  EXPECT_TRUE(caster.hasPendingWork());
}

// In the window the entry maps are drawn in parts, each within a refinement slice (a
// post's 23K faces took about a whole slice): the same maps, so the same picture bit for bit.
TEST_F(RayCast, EntryMapsDrawnInPartsGiveTheSynchronousFrame) {
  const Mesh grid = test::tetGrid(12, 12, 12);  // 1728 boundary faces
  const Camera camera = isoCamera(grid);
  caster_->setVolume(grid, FieldLocation::Node, field(grid));
  caster_->setTransferFunction(kTf);
  caster_->setTerminationThreshold(0.0);
  auto& caster = rayCaster(*caster_);
  const std::vector<float> synchronous = gpuImage(camera, 128, 96);
  ASSERT_TRUE(caster.lastFrame().entryMaps);
  caster.setAsynchronousUpdates(true);
  caster.setFrameBudget(1e-3, 1e-3);  // the smallest slices: a part of the maps each
  for (int i = 0; i < 100000 && (i == 0 || caster.hasPendingWork()); ++i) (void)gpuImage(camera, 128, 96);
  ASSERT_FALSE(caster.hasPendingWork());
  EXPECT_TRUE(caster.lastFrame().entryMaps);
  EXPECT_GT(caster.lastFrame().entryMapParts, 2) << "the maps took several parts";
  EXPECT_EQ(gpuImage(camera, 128, 96), synchronous);
}

// Neighbours more than 2^21 tets apart in the numbering do not fit a packed field: they go
// to the sorted pairs after the packed words, which the shader searches. A tet grid of 2.2M
// tets in a shuffled order has tens of thousands of them: the packed adjacency decodes to
// faceNeighbors' own, and the GPU walk through them draws what the CPU walk draws.
TEST_F(RayCast, NeighboursFarApartInTheNumberingAreFoundInTheirPairs) {
  const Mesh grid = test::tetGrid(72, 72, 72);
  std::vector<std::size_t> order(grid.cellCount());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937(5));
  Mesh shuffled;
  shuffled.nodes = grid.nodes;
  shuffled.reserveCells(grid.cellCount(), grid.cellCount() * 4);
  for (std::size_t c : order) shuffled.addCell(CellType::Tet4, grid.cellNodes(c));
  std::vector<double> values(grid.nodeCount());
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = 0.05 * grid.nodes[i].x + 0.03 * grid.nodes[i].y;

  const volume::TetMeshGpu gpu = volume::buildTetMeshGpu(shuffled, FieldLocation::Node, values);
  ASSERT_GT(gpu.farNeighbors, 1000u);
  std::vector<glm::uvec4> tets(gpu.tetCount);
  for (std::size_t t = 0; t < tets.size(); ++t) tets[t] = gpu.tetNodes(t);
  const std::vector<glm::ivec4> expected = faceNeighbors(tets);
  for (std::size_t t = 0; t < tets.size(); ++t) ASSERT_EQ(gpu.neighborsOf(t), expected[t]) << "tet " << t;

  const TransferFunction tf({{0.0, {0.2, 0.4, 1.0}, 0.02}, {3.6, {1.0, 0.5, 0.1}, 0.08}, {5.8, {1.0, 1.0, 0.9}, 0.03}});
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  caster_->setTerminationThreshold(0.0);
  caster_->setTransferFunction(tf);
  caster_->setVolume(shuffled, FieldLocation::Node, values);
  const Camera camera = isoCamera(shuffled);
  const auto walked = gpuImage(camera, 24, 24);
  const volume::TetWalkMesh walk(shuffled, FieldLocation::Node, values);
  volume::CpuRaySettings exact;
  exact.terminationTransmittance = 0.0;
  const volume::CpuImage cpu = volume::renderCpu(walk, tf, camera, 24, 24, exact);
  ASSERT_EQ(walked.size(), cpu.rgba.size());
  double apart = 0.0;
  for (std::size_t i = 0; i < walked.size(); ++i) apart = std::max(apart, double(std::abs(walked[i] - cpu.rgba[i])));
  EXPECT_LT(apart, 1e-3) << "the GPU walk through far neighbours against the CPU walk";
}

// A mesh of positive tet4 cells, all kept, is its own list of tets on the way to the GPU:
// shared, not copied. One inverted cell makes a list of their own, that cell turned over.
TEST_F(RayCast, APositiveTetMeshIsItsOwnTetListOnTheWayToTheGpu) {
  const Mesh grid = test::tetGrid(3, 3, 3);
  const volume::TetMeshGpu shared = volume::buildTetMeshGpu(grid, FieldLocation::Node, field(grid));
  ASSERT_TRUE(shared.sharedCells);
  EXPECT_TRUE(shared.sharedCells->sharesCellsWith(grid));
  EXPECT_TRUE(shared.tets.empty());
  EXPECT_EQ(shared.tetNodes(7), glm::uvec4(grid.cellNodes(7)[0], grid.cellNodes(7)[1], grid.cellNodes(7)[2],
                                            grid.cellNodes(7)[3]));
  Mesh turned;
  turned.nodes = grid.nodes;
  for (std::size_t c = 0; c < grid.cellCount(); ++c) {
    const auto n = grid.cellNodes(c);
    const NodeIndex cell[4] = {n[0], c == 0 ? n[2] : n[1], c == 0 ? n[1] : n[2], n[3]};
    turned.addCell(CellType::Tet4, cell);
  }
  const volume::TetMeshGpu own = volume::buildTetMeshGpu(turned, FieldLocation::Node, field(turned));
  EXPECT_FALSE(own.sharedCells);
  ASSERT_EQ(own.tets.size(), grid.cellCount());
  EXPECT_EQ(own.tetNodes(0), shared.tetNodes(0)) << "the inverted cell is drawn turned over";
  EXPECT_EQ(own.neighbors, shared.neighbors);
}

TEST_F(RayCast, HiddenTetsAreSkippedWithoutChangingThePicture) {
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  expectSkippingChangesNothing("raycast");
}
