// SPDX-License-Identifier: MIT
// How the window reads a model, alone (a plain main window, no OpenGL): one file at a time
// on a worker, the outcome handed back with the model or an error naming the file, the
// last file and options kept; the reader options dialog fills in what was used and gives
// back what was typed.
#include "gui/ModelLoader.hpp"
#include "gui/ReaderOptionsDialog.hpp"

#include "support/WindowParts.hpp"

#include <QApplication>
#include <QLineEdit>
#include <QTest>

#include <filesystem>
#include <memory>
#include <optional>

using namespace volpost;
using namespace volpost::app;

namespace {

// A reader with two options, for the dialog alone.
class TwoOptionReader : public MeshReader {
 public:
  std::string formatName() const override { return "Two-option test format"; }
  std::vector<std::string> extensions() const override { return {"two"}; }
  int sniff(std::string_view) const override { return 0; }
  std::unique_ptr<Model> read(const std::string&, const Progress&) const override { return nullptr; }
  std::vector<ReaderOption> options() const override {
    return {{"inline-byte", "BYTE", "where the inline number is (default 189)"},
            {"scale", "FACTOR", "multiplies the values (default 1)"}};
  }
};

QString dataFile(const char* relative) {
  return QString::fromStdString((std::filesystem::path(VOLPOST_TEST_DATA) / relative).string());
}

}  // namespace

class ModelLoaderTest : public QObject {
  Q_OBJECT

 private:
  std::unique_ptr<QMainWindow> window_;
  ModelLoader* loader_ = nullptr;

  // Opens a file and waits for its outcome.
  ModelRead read(const QString& path, const ReaderOptions& options = {}) {
    std::optional<ModelRead> outcome;
    if (!loader_->open(path, options, [&](const ModelRead& r) { outcome = r; })) return {};
    for (int i = 0; i < 1200 && !outcome; ++i) QTest::qWait(25);
    return outcome.value_or(ModelRead{});
  }

 private slots:
  void init() {
    window_ = std::make_unique<QMainWindow>();
    loader_ = new ModelLoader(*window_, meshio::allReadersRegistry());
  }

  void cleanup() { window_.reset(); }

  void aModelIsReadAndItsPathAndOptionsKept() {
    const ModelRead r = read(dataFile("bar/bar_tet4.vtu"));
    QVERIFY2(r.session, qPrintable(r.error));
    QVERIFY(r.session->model().cellCount() > 0);
    QCOMPARE(loader_->lastPath(), dataFile("bar/bar_tet4.vtu"));
    QVERIFY(!loader_->busy());
    // An option the reader does not take is refused by name; the options are kept for
    // Reader Options... to show.
    const ModelRead refused = read(dataFile("bar/bar_tet4.vtu"), {{"unused", "1"}});
    QVERIFY(!refused.session);
    QVERIFY2(refused.error.contains("unused=1") && refused.error.contains("takes no options"),
             qPrintable(refused.error));
    QCOMPARE(loader_->lastOptions().at("unused"), std::string("1"));
  }

  void aMissingFileGivesAnErrorNamingIt() {
    const ModelRead r = read(dataFile("no/such/model.vtu"));
    QVERIFY(!r.session);
    QVERIFY(!r.cancelled);
    QVERIFY2(r.error.contains("model.vtu"), qPrintable(r.error));
    QCOMPARE(loader_->lastPath(), dataFile("no/such/model.vtu"));  // Reader Options... tries it again
  }

  void oneFileAtATime() {
    std::optional<ModelRead> first;
    QVERIFY(loader_->open(dataFile("bar/bar_tet4.vtu"), {}, [&](const ModelRead& r) { first = r; }));
    QVERIFY(loader_->busy());
    QVERIFY(!loader_->open(dataFile("bar/bar_tet4.vtk"), {}, [](const ModelRead&) {}));
    QCOMPARE(window_->statusBar()->currentMessage(), QString("Still loading the previous file"));
    QTRY_VERIFY_WITH_TIMEOUT(first.has_value(), 30000);
    QVERIFY(first->session);
    QCOMPARE(loader_->lastPath(), dataFile("bar/bar_tet4.vtu"));
  }

  void withNoFileThereAreNoReaderOptionsToAsk() {
    QVERIFY(!loader_->askReaderOptions());
    QVERIFY(window_->statusBar()->currentMessage().startsWith("Open a model first"));
  }

  void theOptionsDialogShowsTheCurrentOptionsAndGivesBackWhatIsTyped() {
    const TwoOptionReader reader;
    ReaderOptionsDialog dialog(reader, "cube.two", {{"inline-byte", "17"}});
    auto* inlineByte = dialog.findChild<QLineEdit*>("readerOption_inline-byte");
    auto* scale = dialog.findChild<QLineEdit*>("readerOption_scale");
    QVERIFY(inlineByte && scale);
    QCOMPARE(inlineByte->text(), QString("17"));
    QVERIFY(scale->text().isEmpty());
    QCOMPARE(scale->placeholderText(), QString("FACTOR"));
    QCOMPARE(dialog.chosen(), (ReaderOptions{{"inline-byte", "17"}}));  // an empty field keeps the default
    scale->setText(" 2.5 ");
    inlineByte->clear();
    QCOMPARE(dialog.chosen(), (ReaderOptions{{"scale", "2.5"}}));
  }
};

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");  // no display needed
  QApplication app(argc, argv);
  ModelLoaderTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "ModelLoaderTest.moc"
