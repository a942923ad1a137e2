// SPDX-License-Identifier: MIT
#include "SettledView.hpp"

#include "Viewport.hpp"

namespace volpost::app {

SettledView::SettledView(Viewport* view, int minimumMs, int limitMs, QObject* parent)
    : QObject(parent), view_(view), framesBefore_(view->paintedFrames()), minimumMs_(minimumMs), limitMs_(limitMs) {
  timer_.setInterval(50);
  connect(&timer_, &QTimer::timeout, this, &SettledView::poll);
  clock_.start();
  timer_.start();
}

void SettledView::poll() {
  if (clock_.elapsed() < minimumMs_) return;
  const bool calm = view_->paintedFrames() > framesBefore_ && !view_->isRefining();
  calmPolls_ = calm ? calmPolls_ + 1 : 0;
  if (calmPolls_ >= 2) {
    timer_.stop();
    emit settled();
  } else if (clock_.elapsed() > limitMs_) {
    timer_.stop();
    emit timedOut();
  }
}

}  // namespace volpost::app
