// SPDX-License-Identifier: MIT
// Frame rates in the real window: opens each model in volpost's main window, shows the
// volume with the renderer the window picks, sizes the view, and drags it with synthetic
// mouse moves (a move every 16 ms, as a mouse reports them) for a few seconds, then lets go.
// The screen must hold the window around a view of that size (xvfb-run's -screen option).
// The view's own frame timing (View > Show Frame Rate) gives, per drag: frames answered,
// frames per second while dragging, the median time from an input to the frame that shows it,
// and the time from the last move to the full picture. Run on a display (xvfb-run -a).
//   volpost_window_bench [--size 1024x768] [--drags 3] [--seconds 3] [--kuhn N] [--model FILE]...
#include "gui/MainWindow.hpp"
#include "gui/Viewport.hpp"

#include "host/VtuWriter.hpp"

#include "KuhnGrid.hpp"

#include <volpost/core/Model.hpp>
#include <volpost/plugin/PluginManager.hpp>

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QMouseEvent>
#include <QSignalSpy>
#include <QTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

using namespace volpost;
using namespace volpost::app;

namespace {

// n^3 cubes of 6 tets on [0, 1]^3 (the benches' Kuhn grid, scaled, every tet wound outward
// as a mesher writes them) with a smooth wave at every node, written as .vtu.
std::string writeKuhnGrid(int n, const std::filesystem::path& dir) {
  const Mesh grid = bench::kuhnGrid(n);
  auto model = std::make_shared<Model>();
  Mesh& m = model->mesh();
  std::vector<double> wave;
  for (const glm::dvec3& node : grid.nodes) {
    const glm::dvec3 p = node / double(n);
    m.nodes.push_back(p);
    wave.push_back(std::sin(6.0 * p.x) * std::cos(5.0 * p.y) + p.z);
  }
  for (std::size_t c = 0; c < grid.cellCount(); ++c) {
    const auto nodes = grid.cellNodes(c);
    NodeIndex t[4] = {nodes[0], nodes[1], nodes[2], nodes[3]};
    const glm::dvec3 p0 = m.nodes[t[0]];
    if (glm::dot(m.nodes[t[1]] - p0, glm::cross(m.nodes[t[2]] - p0, m.nodes[t[3]] - p0)) < 0.0) std::swap(t[2], t[3]);
    m.addCell(CellType::Tet4, t);
  }
  model->fields.push_back(Field::fromValues("wave", FieldLocation::Node, 1, {wave}));
  const std::filesystem::path path = dir / ("volpost_window_bench_kuhn_" + std::to_string(n) + ".vtu");
  writeVtu(*model, path.string());
  return path.string();
}

struct DragResult {
  std::size_t frames = 0;
  double perSecond = 0.0, inputToFrameMs = 0.0, toFullMs = 0.0;
};

// One drag across the view: a move every 16 ms for `seconds`, then the release; waits for
// the full picture (at most a minute).
DragResult drag(Viewport& view, double seconds, int direction) {
  QTest::qWait(300);
  view.setShowFrameRate(false);
  view.setShowFrameRate(true);  // measured from here
  QPoint at = view.rect().center();
  QTest::mousePress(&view, Qt::LeftButton, {}, at);
  QElapsedTimer clock;
  clock.start();
  int step = 0;
  while (clock.elapsed() < seconds * 1000.0) {
    at += QPoint(direction * (step % 20 < 10 ? 3 : -3), 1 - step % 3);  // back and forth
    ++step;
    QMouseEvent move(QEvent::MouseMove, QPointF(at), view.mapToGlobal(QPointF(at)), Qt::LeftButton, Qt::LeftButton,
                     Qt::NoModifier);
    QApplication::sendEvent(&view, &move);
    QTest::qWait(16);
  }
  QTest::mouseRelease(&view, Qt::LeftButton, {}, at);
  QElapsedTimer waiting;
  waiting.start();
  while (waiting.elapsed() < 60000 && view.drawing().hasPendingWork()) QTest::qWait(10);
  QTest::qWait(200);  // the full picture presented
  const FrameTimes::Summary s = view.frameTimes();
  return {s.framesAnswered, s.framesPerSecond.value_or(0.0), s.inputToFrameMs.value_or(std::nan("")),
          s.changeToFullMs.value_or(std::nan(""))};
}

bool open(MainWindow& window, const QString& path) {
  QSignalSpy finished(&window, &MainWindow::loadFinished);
  window.openFile(path);
  if (!finished.wait(600000)) return false;
  return finished.first().first().toBool();
}

}  // namespace

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  int width = 1024, height = 768, drags = 3, kuhn = 55;
  double seconds = 3.0;
  std::vector<std::string> models;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool more = i + 1 < argc;
    if (a == "--size" && more) std::sscanf(argv[++i], "%dx%d", &width, &height);
    else if (a == "--drags" && more) drags = std::max(1, std::atoi(argv[++i]));
    else if (a == "--seconds" && more) seconds = std::max(0.5, std::atof(argv[++i]));
    else if (a == "--kuhn" && more) kuhn = std::atoi(argv[++i]);
    else if (a == "--model" && more) models.push_back(argv[++i]);
    else {
      std::fprintf(stderr,
                   "usage: volpost_window_bench [--size WxH] [--drags N] [--seconds S] [--kuhn N (0: none)] "
                   "[--model FILE]...\n");
      return 2;
    }
  }
  if (models.empty()) {
    const std::string fine = VOLPOST_SHARED_DATA "/post/fine/post_fine.vtu";
    if (std::filesystem::exists(fine)) models.push_back(fine);
    else std::printf("(%s is not here: the generated grid only)\n", fine.c_str());
  }
  std::string generated;
  if (kuhn > 0) {
    std::printf("writing a Kuhn grid of %d^3 cubes (%d tets) ...\n", kuhn, 6 * kuhn * kuhn * kuhn);
    generated = writeKuhnGrid(kuhn, std::filesystem::temp_directory_path());
    models.push_back(generated);
  }

  PluginManager plugins;
  plugins.loadFrom({VOLPOST_PLUGIN_DIR});
  std::printf(
      "\n| model | tets | renderer | view | drag | frames | frames/s while dragging | input to frame ms | "
      "last move to full picture s |\n|---|---:|---|---|---:|---:|---:|---:|---:|\n");
  for (const std::string& path : models) {
    MainWindow window(plugins);
    window.resize(width + 400, height + 200);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window)) {
      std::fprintf(stderr, "no display: run under xvfb-run -a\n");
      return 1;
    }
    if (!open(window, QString::fromStdString(path))) {
      std::fprintf(stderr, "%s: not opened\n", path.c_str());
      continue;
    }
    Viewport& view = *window.viewport();
    // The view at the asked size (the docks keep theirs): the window grows around it.
    view.setFixedSize(width, height);
    QTest::qWait(300);
    if (view.width() != width || view.height() != height)
      std::fprintf(stderr, "the view is %dx%d, not %dx%d: a larger screen (xvfb-run -s \"-screen 0 2560x1600x24\")\n",
                   view.width(), view.height(), width, height);
    window.findChild<QAction*>("volumeAction")->setChecked(true);
    QTest::qWait(200);
    while (view.drawing().hasPendingWork()) QTest::qWait(20);
    const std::size_t tets = view.uploadedTetCount();
    for (int d = 0; d < drags; ++d) {
      const DragResult r = drag(view, seconds, d % 2 ? -1 : 1);
      std::printf("| %s | %zu | %s | %dx%d | %d | %zu | %.1f | %.0f | %.2f |\n",
                  std::filesystem::path(path).filename().string().c_str(), tets, view.scene().volume().renderer.c_str(),
                  view.width(), view.height(), d + 1, r.frames, r.perSecond, r.inputToFrameMs, r.toFullMs / 1000.0);
      std::fflush(stdout);
    }
  }
  if (!generated.empty()) std::filesystem::remove(generated);
  return 0;
}
