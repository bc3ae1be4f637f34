/**
 * @file CommandLine.h
 * @brief The command lines of every tool, on CLI11: one set-up, the options' rules with the
 * messages the tools give, and one way of reporting errors.
 *
 * A tool makes a CLI::App, calls SetUpCommandLine(), adds its options (those with a rule
 * through AddValue(), AddNumber() or AddChoice()) and calls ParseCommandLine(). For every
 * tool:
 * - a long option that takes one value takes the next argument, whatever it looks like
 *   (`--view -Y`, `--reduction -1`), or the text after '=' (`--reduction=0.5`);
 * - an option given twice keeps its last value;
 * - `-h` and `--help` print the help (usage lines first) and end the tool with status 0;
 * - a bad command line prints "PROGRAM: message" and "Try 'PROGRAM --help'." on stderr and
 *   ends the tool with its usage status (2 for most tools).
 */
#ifndef CommandLine_h
#define CommandLine_h

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace colordecimation
{
namespace tools
{

/// A bad command line, with the whole message to print.
class UsageError : public CLI::ParseError
{
public:
  explicit UsageError(const std::string& message)
    : CLI::ParseError("UsageError", message, CLI::ExitCodes::ValidationError)
  {
  }
};

/// What a tool says about a bad value, given the text of the value.
using Complaint = std::function<std::string(const std::string& text)>;

/// "RULE (got 'TEXT')": color-decimate's and the benchmark's wording.
Complaint RuleComplaint(const std::string& rule);

/// "bad value 'TEXT' for NAME": the wording of the fidelity tools.
Complaint BadValueComplaint(const std::string& name);

/// `message` whatever the value was.
Complaint FixedComplaint(const std::string& message);

/**
 * Sets up `app` (made with its description and the program's name) for one of the tools:
 * `usage` (one or more "Usage: ..." lines) opens the help, before the description; `-h,
 * --help` shows the help; the last of repeated values counts.
 */
void SetUpCommandLine(CLI::App& app, const std::string& usage);

/**
 * Parses the command line into `app`'s options. Returns -1 when the tool should go on, 0
 * when the help was printed, and `usageStatus` when the command line is bad (the message is
 * printed).
 */
int ParseCommandLine(CLI::App& app, int argc, char* argv[], int usageStatus = 2);

/// Prints a usage error as ParseCommandLine() does, for the checks a tool makes after it.
int ReportUsageError(const CLI::App& app, const std::string& message, int usageStatus = 2);

/// A finite decimal number that is the whole text (std::strtod).
bool ParseNumber(const std::string& text, double& value);

/// A whole number in base 10 that is the whole text and fits in a long long.
bool ParseWholeNumber(const std::string& text, long long& value);

/// A count such as 1234, 250k or 1.5M (at most 1e10); rounded to a whole number.
bool ParseCount(const std::string& text, long long& value);

/**
 * --NAME TEXT: `apply` stores the value and returns true, or returns false when TEXT is
 * not acceptable; the parse then stops with complaint(TEXT).
 */
CLI::Option* AddValue(CLI::App& app, const std::string& name,
                      std::function<bool(const std::string&)> apply, Complaint complaint,
                      const std::string& help);

/// --NAME X: a finite number from `lo` to `hi` (ParseNumber).
CLI::Option* AddNumber(CLI::App& app, const std::string& name, double& value, double lo, double hi,
                       Complaint complaint, const std::string& help);

/// --NAME WORD: one of the `choices`' words, each giving its value.
template <typename T>
CLI::Option* AddChoice(CLI::App& app, const std::string& name, T& value,
                       std::vector<std::pair<std::string, T>> choices, Complaint complaint,
                       const std::string& help)
{
  auto apply = [&value, choices](const std::string& text)
  {
    for (const auto& choice : choices)
    {
      if (choice.first == text)
      {
        value = choice.second;
        return true;
      }
    }
    return false;
  };
  return AddValue(app, name, apply, std::move(complaint), help);
}

} // namespace tools
} // namespace colordecimation

#endif
