// SPDX-License-Identifier: MIT
// Pieces the command-line verbs share: plugin loading, progress on stderr, messages.
#pragma once

#include "../core/ModelSession.hpp"

#include <volpost/plugin/PluginManager.hpp>

#include <QCommandLineParser>
#include <QString>

#include <exception>
#include <stdexcept>
#include <memory>
#include <optional>

namespace volpost::app {

/// Loads the plugins from the default folders; warns on stderr about refused ones.
std::unique_ptr<PluginManager> loadPluginsForCli();

/// Progress that draws "label 42%" on stderr when it is a terminal, silent otherwise.
Progress terminalProgress(const std::string& label);

void printError(const QString& message);

/// Command-line arguments as Qt strings without losing bytes: a file name that is not valid
/// UTF-8 keeps each stray byte as a private code (U+DC80..U+DCFF, as Python does), and
/// pathBytes() gives the exact bytes back for opening the file.
QString argumentText(const char* bytes);
std::string pathBytes(const QString& text);

/// Parses a verb's arguments (`verb` is "volpost render" ...). Returns the exit code to
/// leave with at once (0 after --help, whose text names the verb; 2 after printing what
/// is wrong with the arguments), or nullopt to go on.
std::optional<int> parseArguments(QCommandLineParser& parser, const QString& verb, const QStringList& args);

/// The 0-based step of a 1-based --step option; prints what is wrong and gives nullopt.
/// An option the model cannot honour (a quantity it lacks, a step it does not have): a
/// usage error, exit code 2 through exitCodeOf.
struct OptionError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// The written forms of these quantities; OptionError naming the valid ones for one the
/// model does not have.
std::vector<std::string> quantityKeys(const ModelSession& session, const QStringList& names);

/// Throws OptionError when a quantity's field has
/// no step `step` (0-based), naming the field and its step count.
void checkStepExists(const ModelSession& session, const std::vector<std::string>& keys, std::size_t step);

/// --reader-option NAME=VALUE (repeatable), which every verb that reads a model takes:
/// settings of the file's reader, such as SEG-Y header byte positions.
QCommandLineOption readerOptionOption();
/// Its values; OptionError for one that is not NAME=VALUE or names an option twice.
ReaderOptions readerOptionsFrom(const QCommandLineParser& parser, const QCommandLineOption& option);

/// --formula NAME=EXPRESSION (repeatable): a field the calculator computes from the model's
/// quantities (docs/user/calculator.md), usable as any other.
QCommandLineOption formulaOption();
/// Its formulas, in order; OptionError for one that is not NAME=EXPRESSION.
std::vector<FormulaSpec> formulasFrom(const QCommandLineParser& parser, const QCommandLineOption& option);
/// Reads MODEL (`path`) with the verb's --reader-option and --formula values (the formulas
/// read first, so a malformed one is said before the reading), the boundary left for first
/// use; OptionError naming a reader option or formula at fault.
std::shared_ptr<ModelSession> loadWithFormulas(const ReaderRegistry& readers, const std::string& path,
                                               const QCommandLineParser& parser, const QCommandLineOption& readerOption,
                                               const QCommandLineOption& formulaOption);
/// The same on a model read without a session.
void appendFormulas(Model& model, const std::vector<FormulaSpec>& formulas);

/// "WIDTHxHEIGHT", each 1..16384.
bool parseSize(const QString& text, int& w, int& h);

std::optional<std::size_t> parseStep(const QCommandLineParser& parser, const QCommandLineOption& option);

/// Runs a verb's work and returns its exit code; a cancel (Ctrl+C on the progress) is 1,
/// an error is printed and is 1.
template <typename Work>
int exitCodeOf(Work&& work) {
  try {
    return work();
  } catch (const Cancelled&) {
    return 1;
  } catch (const OptionError& e) {  // what the README promises for usage errors
    printError(e.what());
    return 2;
  } catch (const ReaderOptionError& e) {
    printError(e.what());
    return 2;
  } catch (const std::exception& e) {
    printError(e.what());
    return 1;
  }
}

}  // namespace volpost::app
