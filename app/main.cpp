// SPDX-License-Identifier: MIT
// volpost: the window (no verb) or a command-line verb (info, render, plugins).
#include "cli/CliSupport.hpp"
#include "cli/Commands.hpp"
#include "core/PictureFile.hpp"
#include "gui/MainWindow.hpp"
#include "gui/SettledView.hpp"
#include "gui/Viewport.hpp"

#include <volpost/core/ResourceLimits.hpp>
#include <volpost/core/Version.hpp>

#include <OpenMesh/Core/System/omstream.hh>

#include <QAction>
#include <QApplication>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QGuiApplication>
#include <QSurfaceFormat>
#include <QTimer>

#include <csignal>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace {

// The window's picture once the view has settled (SettledView: not the quick frame shown
// while the full one is computed); after ten minutes still refining it is saved as shown,
// with a warning. Exit code 0 once written, 1 if not.
void saveWhenSettled(volpost::app::MainWindow& window, const QString& shot) {
  auto* wait = new volpost::app::SettledView(window.viewport(), 300, 10 * 60 * 1000, &window);
  const auto save = [&window, shot] {
    try {
      volpost::app::savePicture(window.grab().toImage(), shot);
      QApplication::exit(0);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "volpost: error: %s\n", e.what());
      QApplication::exit(1);
    }
  };
  QObject::connect(wait, &volpost::app::SettledView::settled, &window, save);
  QObject::connect(wait, &volpost::app::SettledView::timedOut, &window, [save] {
    std::fprintf(stderr, "volpost: warning: the picture was still being refined after 10 minutes; saved as shown\n");
    save();
  });
}

void printUsage() {
  std::printf(
      "volpost %s - finite-element post-processing and volume rendering\n\n"
      "usage:\n"
      "  volpost [MODEL] [--field Q] [--volume] [--state FILE] [--screenshot FILE]\n"
      "                                    open the window (optionally on MODEL, colored by Q,\n"
      "                                    or on a saved state)\n"
      "  volpost info MODEL                counts, bounds, fields and defects of MODEL\n"
      "  volpost render MODEL -o OUT.png   render MODEL headless (see volpost render --help)\n"
      "  volpost plugins                   list plugins and why any was refused\n"
      "  volpost convert MODEL OUT.vtu     write MODEL (all fields and steps) for ParaView\n"
      "  volpost surface MODEL OUT.obj     boundary (or --field Q --iso V: iso-surface) as obj/ply/stl/off\n"
      "  volpost probe MODEL --field Q --at X,Y,Z   value of Q at a point\n"
      "  volpost streamlines MODEL --field V --seeds SPEC -o lines.vtp   streamlines to .vtp/.csv\n"
      "  volpost plot MODEL --from X,Y,Z --to X,Y,Z --field Q -o plot.png   quantities along a line (also --csv)\n"
      "  volpost --version | --help\n\n"
      "Any verb or the window also takes --memory-budget SIZE (512M, 8G, ...): files that would need\n"
      "more are refused with a message (default: 3/4 of the memory, or $VOLPOST_MEMORY_BUDGET).\n"
      "And --gpu-memory-budget SIZE: the most GPU memory a volume's data may hold at once; regular\n"
      "grids larger than it are drawn in bricks streamed through it (default: 3/4 of what an NVIDIA\n"
      "GPU reports, else no limit, or $VOLPOST_GPU_MEMORY_BUDGET).\n",
      VOLPOST_VERSION);
}

QStringList argsAfter(int argc, char** argv, int first) {
  QStringList out;
  for (int i = first; i < argc; ++i) out << volpost::app::argumentText(argv[i]);
  return out;
}

// Without a display Qt aborts with a page of advice about platform plugins; one line says
// what is missing and what works instead.
bool displayAvailable() {
  const auto set = [](const char* name) {
    const char* value = std::getenv(name);
    return value && *value;
  };
  return set("DISPLAY") || set("WAYLAND_DISPLAY") || set("QT_QPA_PLATFORM");
}

int runWindow(int argc, char** argv) {
  if (!displayAvailable()) {
    std::fprintf(stderr, "volpost: error: no display to open the window on (DISPLAY is not set); "
                         "`volpost render` draws pictures without one\n");
    return 1;
  }
  QSurfaceFormat format;
  format.setVersion(4, 5);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  format.setSamples(4);
  QSurfaceFormat::setDefaultFormat(format);
  QApplication app(argc, argv);
  QApplication::setApplicationName("volpost");
  QApplication::setApplicationVersion(VOLPOST_VERSION);
  QCommandLineParser parser;
  parser.setApplicationDescription("volpost: the window (see volpost --help for the command-line verbs).");
  parser.addPositionalArgument("MODEL", "model to open");
  const QCommandLineOption field("field", "quantity to color by, e.g. S.mises", "Q");
  const QCommandLineOption screenshot("screenshot", "save the window to FILE once MODEL is shown, then quit", "FILE");
  const QCommandLineOption volume("volume", "show the result as a volume (View > Volume Rendering)");
  const QCommandLineOption state("state", "open a state file saved by File > Save State (or volpost render "
                                          "--save-state): its model and its view", "FILE");
  parser.addOptions({field, screenshot, volume, state});
  parser.addHelpOption();
  parser.process(app);

  volpost::PluginManager plugins;
  plugins.loadFrom(volpost::PluginManager::defaultSearchPaths());
  volpost::app::MainWindow window(plugins);
  window.show();
  const QString shot = parser.value(screenshot);
  // The screenshot is taken once the view is there; a failure to get there or to write it
  // is exit code 1, with the reason on stderr.
  const auto takeScreenshot = [&window, shot](bool ok, const QString& message) {
    if (shot.isEmpty()) return;
    if (!ok) {
      std::fprintf(stderr, "volpost: error: %s\n", qPrintable(message.isEmpty() ? QString("cannot open the model") : message));
      QTimer::singleShot(0, &window, [] { QApplication::exit(1); });
      return;
    }
    saveWhenSettled(window, shot);
  };
  if (parser.isSet(state)) {
    QObject::connect(&window, &volpost::app::MainWindow::stateApplied, &window, takeScreenshot);
    window.openStateFile(parser.value(state));
  } else if (!parser.positionalArguments().isEmpty()) {
    const QString wanted = parser.value(field);
    const bool asVolume = parser.isSet(volume);
    QObject::connect(&window, &volpost::app::MainWindow::loadFinished, &window,
                     [&window, wanted, asVolume, takeScreenshot](bool ok, const QString& message) {
                       if (ok && !wanted.isEmpty() && !window.selectQuantity(wanted))
                         std::fprintf(stderr, "volpost: warning: no quantity '%s' in this model\n", qPrintable(wanted));
                       if (ok && asVolume)
                         if (auto* action = window.findChild<QAction*>("volumeAction"); action && action->isEnabled())
                           action->setChecked(true);
                       takeScreenshot(ok, message);
                     });
    window.openFile(parser.positionalArguments().first());
  } else if (!shot.isEmpty()) {
    std::fprintf(stderr, "volpost: error: --screenshot needs a MODEL or --state FILE\n");
    return 2;
  }
  return app.exec();
}

}  // namespace

// "--memory-budget SIZE" and "--gpu-memory-budget SIZE" (or =SIZE) anywhere on the command
// line set the budgets for every verb and the window, and are taken out of the arguments.
// Returns false (after saying why) when SIZE is not a size.
bool takeBudgets(int& argc, char** argv) {
  const std::pair<std::string, void (*)(std::size_t)> options[] = {{"--memory-budget", volpost::setMemoryBudget},
                                                                    {"--gpu-memory-budget", volpost::setGpuMemoryBudget}};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    for (const auto& [name, set] : options) {
      std::string value;
      int used = 0;
      if (arg == name && i + 1 < argc) value = argv[i + 1], used = 2;
      else if (arg.rfind(name + "=", 0) == 0) value = arg.substr(name.size() + 1), used = 1;
      else continue;
      const std::size_t bytes = volpost::parseByteSize(value);
      if (!bytes) {
        std::fprintf(stderr, "volpost: error: %s %s is not a size (512M, 8G, 1.5T)\n", name.c_str(), value.c_str());
        return false;
      }
      set(bytes);
      for (int k = i; k + used < argc; ++k) argv[k] = argv[k + used];
      argc -= used;
      --i;
      break;
    }
  }
  return true;
}

int main(int argc, char** argv) {
  // A file-size limit (ulimit -f) must end a write with an error we report, not kill us.
  std::signal(SIGXFSZ, SIG_IGN);
  // OpenMesh reports each face it refuses (a non-manifold vertex) on stderr; the boundary
  // and iso-surface builders keep every such face with vertices of their own and count it.
  omerr().disable();
  if (!takeBudgets(argc, argv)) return 2;
  const char* verb = argc >= 2 ? argv[1] : "";
  if (!std::strcmp(verb, "--help") || !std::strcmp(verb, "-h") || !std::strcmp(verb, "help")) {
    printUsage();
    return 0;
  }
  if (!std::strcmp(verb, "--version")) {
    std::printf("volpost %s (SDK %s)\n", VOLPOST_VERSION, VOLPOST_SDK_VERSION);
    return 0;
  }
  if (!std::strcmp(verb, "info") || !std::strcmp(verb, "plugins") || !std::strcmp(verb, "convert") ||
      !std::strcmp(verb, "surface") || !std::strcmp(verb, "probe") || !std::strcmp(verb, "streamlines")) {
    QCoreApplication app(argc, argv);
    const QStringList args = argsAfter(argc, argv, 2);
    if (!std::strcmp(verb, "info")) return volpost::app::runInfo(args);
    if (!std::strcmp(verb, "convert")) return volpost::app::runConvert(args);
    if (!std::strcmp(verb, "surface")) return volpost::app::runSurface(args);
    if (!std::strcmp(verb, "probe")) return volpost::app::runProbe(args);
    if (!std::strcmp(verb, "streamlines")) return volpost::app::runStreamlines(args);
    return volpost::app::runPlugins(args);
  }
  if (!std::strcmp(verb, "render") || !std::strcmp(verb, "plot")) {
    // Rendering uses EGL, never a display; Qt is only needed for the legend's text.
    qputenv("QT_QPA_PLATFORM", "offscreen");
    if (qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR")) {  // what Qt would pick, without its warning
      const QByteArray dir = "/tmp/runtime-" + QByteArray::number(getuid());
      mkdir(dir.constData(), 0700);
      qputenv("XDG_RUNTIME_DIR", dir);
    }
    QGuiApplication app(argc, argv);
    if (!std::strcmp(verb, "plot")) return volpost::app::runPlot(argsAfter(argc, argv, 2));
    return volpost::app::runRender(argsAfter(argc, argv, 2));
  }
  return runWindow(argc, argv);
}
