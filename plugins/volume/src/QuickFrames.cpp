// SPDX-License-Identifier: MIT
#include "QuickFrames.hpp"

#include "ImageComposite.hpp"

#include <algorithm>
#include <cmath>

namespace volpost::volume {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

bool QuickFrames::viewChanged(const RenderContext& ctx, std::uint64_t revision, std::size_t meshRevision, int extra) {
  Key key;
  key.viewProjection = ctx.camera.projectionMatrix(ctx.aspect()) * ctx.camera.viewMatrix();
  key.width = ctx.width;
  key.height = ctx.height;
  key.revision = revision;
  key.meshRevision = meshRevision;
  key.depthTexture = ctx.depthTexture;
  key.extra = extra;
  if (key == key_) return false;
  key_ = key;
  refining_ = false;
  return true;
}

void QuickFrames::forget() {
  key_ = {};
  refining_ = false;
}

int QuickFrames::reductionFor(int width, int height) const {
  const double pixels = double(width) * double(height);
  if (quickFramesElsewhere_ && fullMsPerPixel_ > 0.0 && fullMsPerPixel_ * pixels <= quickMs_) return 1;
  if (msPerPixel_ <= 0.0) return 4;  // nothing measured yet: a cautious first guess
  const int reduction = std::clamp(int(std::ceil(std::sqrt(msPerPixel_ * pixels / quickMs_))), 1, 16);
  return quickFramesElsewhere_ ? std::max(reduction, 2) : reduction;  // 1 would be the full frame's way
}

RenderContext QuickFrames::quickContext(const RenderContext& ctx, int reduction) {
  RenderContext quick = ctx;
  quick.width = std::max(1, ctx.width / reduction);
  quick.height = std::max(1, ctx.height / reduction);
  quick.depthTexture = 0;
  if (!quickImage_ || quickWidth_ != quick.width || quickHeight_ != quick.height) {
    quickImage_ = floatImageTexture(quick.width, quick.height);
    quickWidth_ = quick.width;
    quickHeight_ = quick.height;
  }
  return quick;
}

void QuickFrames::measured(double ms, int width, int height) {
  const double pixels = double(width) * double(height);
  if (pixels > 0.0 && ms > 0.0) msPerPixel_ = ms / pixels;
}

void QuickFrames::measuredFull(double ms, int width, int height) {
  const double pixels = double(width) * double(height);
  if (pixels > 0.0 && ms > 0.0) fullMsPerPixel_ = ms / pixels;
}

void QuickFrames::release() {
  quickImage_.reset();
  quickWidth_ = quickHeight_ = 0;
  forget();
}

}  // namespace volpost::volume
