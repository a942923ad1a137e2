// SPDX-License-Identifier: MIT
#include "RayCaster.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace volpost::volume {

void RayCaster::initialize() {
  volume_.initialize();
  rays_.initialize();
  quick_.release();
}

void RayCaster::release() {
  volume_.release();
  rays_.release();
  quick_.release();
}

void RayCaster::setStepsPerPass(int steps) {
  stepsPerPass_ = std::clamp(steps, 1, kStepsPerPass);
  sliceSteps_ = std::min(sliceSteps_, stepsPerPass_);
}

VolumeStats RayCaster::stats() const {
  VolumeStats s = volume_.stats();
  s.gpuBytes += rays_.bytes() + quick_.bytes();
  return s;
}

double RayCaster::renderWhole(const RenderContext& ctx, GLuint image) {
  lastFrame_ = rays_.renderWhole(volume_, ctx, image, stepsPerPass_);
  return lastFrame_.milliseconds;
}

void RayCaster::beginRefining(const RenderContext& ctx) {
  building_ = {};
  msPerRow_ = 0.0;  // this view's rows cost what they cost: measured again
  mapsPending_ = true;  // drawn by refine(), in parts: not while the view moves
  mapsBegun_ = false;
  beginRefiningBand(ctx, 0);
}

// A band of rows the slice can finish: a dispatch covers its band whatever its steps, and a
// band of the whole 1024x768 picture of a 213K-tet post held the window 4 s on llvmpipe.
// Sized from the last band's cost per row; as rows cost what their rays cross and rows of
// background may be followed by dense ones, never below half the picture's average per
// row (the quick frame's), nor more than twice the last band's rows.
void RayCaster::beginRefiningBand(const RenderContext& ctx, int firstRow) {
  refineFirstRow_ = firstRow;
  const double average = quick_.msPerPixel() * double(ctx.width);
  const double perRow = std::max(msPerRow_, 0.5 * average);
  int fits = perRow > 0.0 ? int(std::clamp(0.8 * quick_.sliceMs() / perRow, 1.0, double(ctx.height))) : ctx.height;
  if (firstRow > 0) fits = std::min(fits, 2 * refineRows_);
  refineRows_ = std::min({rays_.bandRows(ctx.width, ctx.height), ctx.height - firstRow, fits});
  bandMs_ = 0.0;
  ++building_.refinedBands;
  rays_.beginBand(ctx.width, refineRows_);
}

bool RayCaster::refine(const RenderContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  if (mapsPending_ && !drawMapsPart(ctx, start)) return false;
  double lastMs = 0.0;  // the slice's previous dispatch
  for (;;) {
    // Another dispatch only where the slice can hold one like the last.
    if (lastMs > 0.0 && millisecondsSince(start) + lastMs > quick_.sliceMs()) return false;
    const auto passStart = std::chrono::steady_clock::now();
    const std::size_t unfinished =
        rays_.dispatch(volume_, ctx, volume_.image(), refineFirstRow_, refineRows_, sliceSteps_, building_);
    const double ms = millisecondsSince(passStart);
    building_.milliseconds += ms;
    bandMs_ += ms;
    lastMs = ms;
    // Tets per dispatch follow the measured time (a dispatch costs about its steps).
    const double factor = std::clamp(quick_.sliceMs() / std::max(ms, 0.1), 0.25, 4.0);
    sliceSteps_ = std::clamp(int(sliceSteps_ * factor), 16, stepsPerPass_);
    if (unfinished == 0) {
      msPerRow_ = bandMs_ / double(refineRows_);
      if (refineFirstRow_ + refineRows_ >= ctx.height) {
        lastFrame_ = building_;
        quick_.measured(lastFrame_.milliseconds, ctx.width, ctx.height);
        return true;
      }
      beginRefiningBand(ctx, refineFirstRow_ + refineRows_);
    }
    if (millisecondsSince(start) >= quick_.sliceMs()) return false;
  }
}

// The entry maps of the frame being refined, as many faces a call as its slice allows (a
// post of 23K faces took about a slice's time to draw at 1024x768 on llvmpipe); true once
// they are done (or not drawn at all), and the slice's time is not spent.
bool RayCaster::drawMapsPart(const RenderContext& ctx, std::chrono::steady_clock::time_point sliceStart) {
  if (!mapsBegun_) {
    mapsBegun_ = true;
    if (!rays_.beginEntryMaps(volume_, ctx)) {
      mapsPending_ = false;
      return true;
    }
  }
  for (;;) {
    const auto partStart = std::chrono::steady_clock::now();
    const bool done = rays_.drawEntryMapFaces(volume_, ctx, mapFacesPerPart_);
    glFinish();  // the part's time, to size the next one
    ++building_.entryMapParts;
    const double ms = millisecondsSince(partStart);
    const double factor = std::clamp(0.5 * quick_.sliceMs() / std::max(ms, 0.1), 0.25, 4.0);
    mapFacesPerPart_ = std::clamp(std::size_t(double(mapFacesPerPart_) * factor), std::size_t(64), std::size_t(1) << 26);
    if (done) mapsPending_ = false;
    if (millisecondsSince(sliceStart) >= quick_.sliceMs()) return false;
    if (done) return true;
  }
}

void RayCaster::render(const RenderContext& ctx) {
  if (!volume_.initialized() || !volume_.hasTets() || ctx.width <= 0 || ctx.height <= 0) return;
  volume_.prepare(ctx);
  if (!volume_.asynchronous()) {
    quick_.forget();
    renderWhole(ctx, volume_.image());
    volume_.compositeOver(ctx);
    gl::check("RayCaster::render");
    return;
  }
  const GLuint shown = quick_.frame(
      ctx, volume_.revision(), volume_.meshRevision(), 0, volume_.image(),
      [this](const RenderContext& c, GLuint image) { return renderWhole(c, image); },
      [this, &ctx] { beginRefining(ctx); }, [this, &ctx] { return refine(ctx); });
  volume_.compositeOver(ctx, shown);
  gl::check("RayCaster::render");
}

}  // namespace volpost::volume
