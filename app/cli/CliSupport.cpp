// SPDX-License-Identifier: MIT
#include "CliSupport.hpp"

#include <cstdio>
#include <unistd.h>

namespace volpost::app {

std::unique_ptr<PluginManager> loadPluginsForCli() {
  auto plugins = std::make_unique<PluginManager>();
  plugins->loadFrom(PluginManager::defaultSearchPaths());
  for (const PluginRecord& r : plugins->records())
    if (!r.loaded)
      std::fprintf(stderr, "volpost: warning: plugin %s refused: %s\n", qPrintable(r.path), qPrintable(r.error));
  return plugins;
}

Progress terminalProgress(const std::string& label) {
  if (!isatty(STDERR_FILENO)) return Progress();
  auto last = std::make_shared<int>(-1);
  return Progress([label, last](double f, const std::string& stage) {
    const int percent = int(f * 100.0);
    if (percent != *last) {
      *last = percent;
      const std::string what = stage.empty() ? label : stage;
      std::fprintf(stderr, "\r%-24s %3d%%%s", what.c_str(), percent, percent >= 100 ? "\n" : "");
      std::fflush(stderr);
    }
    return true;
  });
}

QString argumentText(const char* bytes) {
  QString out;
  const auto* p = reinterpret_cast<const unsigned char*>(bytes);
  while (*p) {
    const unsigned char c = *p;
    const int length = c < 0x80 ? 1 : (c & 0xE0) == 0xC0 ? 2 : (c & 0xF0) == 0xE0 ? 3 : (c & 0xF8) == 0xF0 ? 4 : 0;
    bool valid = length > 0;
    for (int k = 1; valid && k < length; ++k) valid = (p[k] & 0xC0) == 0x80;
    if (valid) {
      const QString decoded = QString::fromUtf8(reinterpret_cast<const char*>(p), length);
      valid = !decoded.contains(QChar::ReplacementCharacter);  // overlong or surrogate encodings
      if (valid) {
        out += decoded;
        p += length;
        continue;
      }
    }
    out += QChar(char16_t(0xDC00 + c));  // a byte that is not UTF-8, kept
    ++p;
  }
  return out;
}

std::string pathBytes(const QString& text) {
  std::string out;
  for (qsizetype i = 0; i < text.size();) {
    const char16_t u = text[i].unicode();
    if (u >= 0xDC80 && u <= 0xDCFF && !(i > 0 && text[i - 1].isHighSurrogate())) {
      out += char(u - 0xDC00);
      ++i;
      continue;
    }
    const qsizetype n = text[i].isHighSurrogate() && i + 1 < text.size() ? 2 : 1;
    out += text.mid(i, n).toStdString();
    i += n;
  }
  return out;
}

void printError(const QString& message) { std::fprintf(stderr, "volpost: error: %s\n", qPrintable(message)); }

std::optional<int> parseArguments(QCommandLineParser& parser, const QString& verb, const QStringList& args) {
  const QCommandLineOption help = parser.addHelpOption();
  if (!parser.parse(QStringList{verb} + args)) {
    printError(QString("%1: %2 (%1 --help lists the options)").arg(verb, parser.errorText()));
    return 2;
  }
  if (parser.isSet(help)) {
    // Qt names the executable's path in the usage line; the user typed "volpost VERB".
    QString text = parser.helpText();
    const QString usage = "Usage: ";
    if (text.startsWith(usage)) {
      qsizetype end = text.indexOf(" [options]", usage.size());
      if (end < 0 || end > text.indexOf('\n')) end = text.indexOf(' ', usage.size());
      if (end > 0) text.replace(usage.size(), end - usage.size(), verb);
    }
    std::printf("%s", qPrintable(text));
    return 0;
  }
  return std::nullopt;
}

QCommandLineOption readerOptionOption() {
  return QCommandLineOption("reader-option",
                            "A setting of the file's reader, NAME=VALUE (repeatable), e.g. inline-byte=9 for a SEG-Y "
                            "file whose inline numbers are at byte 9 (volpost info --reader-options lists them).",
                            "NAME=VALUE");
}

ReaderOptions readerOptionsFrom(const QCommandLineParser& parser, const QCommandLineOption& option) {
  ReaderOptions options;
  for (const QString& text : parser.values(option)) {
    const qsizetype eq = text.indexOf('=');
    if (eq <= 0 || eq + 1 >= text.size())
      throw OptionError(QString("--reader-option %1 is not NAME=VALUE").arg(text).toStdString());
    const std::string name = text.left(eq).trimmed().toStdString(), value = text.mid(eq + 1).trimmed().toStdString();
    if (!options.emplace(name, value).second)
      throw OptionError(QString("--reader-option %1: %2 is given twice").arg(text, QString::fromStdString(name)).toStdString());
  }
  return options;
}

QCommandLineOption formulaOption() {
  return QCommandLineOption("formula",
                            "A field computed from the model's quantities, NAME=EXPRESSION (repeatable), e.g. "
                            "ratio=S.mises/250, then --field ratio; see docs/user/calculator.md.",
                            "NAME=EXPR");
}

std::vector<FormulaSpec> formulasFrom(const QCommandLineParser& parser, const QCommandLineOption& option) {
  std::vector<FormulaSpec> formulas;
  for (const QString& text : parser.values(option)) {
    try {
      formulas.push_back(parseFormulaText(text.toStdString()));
    } catch (const FormulaError& e) {
      throw OptionError(std::string("--formula: ") + e.what());
    }
  }
  return formulas;
}

std::shared_ptr<ModelSession> loadWithFormulas(const ReaderRegistry& readers, const std::string& path,
                                               const QCommandLineParser& parser, const QCommandLineOption& readerOption,
                                               const QCommandLineOption& formulaOption) {
  const std::vector<FormulaSpec> formulas = formulasFrom(parser, formulaOption);
  auto session = ModelSession::load(readers, path, terminalProgress("reading"), ModelSession::Boundary::OnFirstUse,
                                    readerOptionsFrom(parser, readerOption));
  if (formulas.empty()) return session;
  try {
    return ModelSession::withFormulas(*session, formulas);
  } catch (const FormulaError& e) {
    throw OptionError(e.what());
  }
}

void appendFormulas(Model& model, const std::vector<FormulaSpec>& formulas) {
  try {
    appendFormulaFields(model, formulas);
  } catch (const FormulaError& e) {
    throw OptionError(e.what());
  }
}

std::vector<std::string> quantityKeys(const ModelSession& session, const QStringList& names) {
  std::vector<std::string> keys;
  for (const QString& name : names) {
    try {
      keys.push_back(session.findQuantity(name.toStdString()).key());
    } catch (const std::invalid_argument& e) {
      throw OptionError(e.what());
    }
  }
  return keys;
}

void checkStepExists(const ModelSession& session, const std::vector<std::string>& keys, std::size_t step) {
  for (const std::string& key : keys) {
    const Field& f = session.fieldOf(session.findQuantity(key));
    if (step >= f.stepCount())
      throw OptionError("--step " + std::to_string(step + 1) + ": " + f.name() + " has " +
                                  std::to_string(f.stepCount()) + " step(s)");
  }
}

bool parseSize(const QString& text, int& w, int& h) {
  const QStringList parts = text.toLower().split('x');
  if (parts.size() != 2) return false;
  bool okW = false, okH = false;
  w = parts[0].toInt(&okW);
  h = parts[1].toInt(&okH);
  return okW && okH && w > 0 && h > 0 && w <= 16384 && h <= 16384;
}

std::optional<std::size_t> parseStep(const QCommandLineParser& parser, const QCommandLineOption& option) {
  bool ok = false;
  const int step = parser.value(option).toInt(&ok);
  if (!ok || step < 1) {
    printError(QString("--step %1 is not a step number (1, 2, ...)").arg(parser.value(option)));
    return std::nullopt;
  }
  return std::size_t(step - 1);
}

}  // namespace volpost::app
