#include "CommandLine.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>

namespace colordecimation
{
namespace tools
{
namespace
{

/// CLI11's help, with the tool's usage lines first and its description after them.
class ToolFormatter : public CLI::Formatter
{
public:
  explicit ToolFormatter(std::string usage)
    : Usage(std::move(usage))
  {
  }

  std::string make_help(const CLI::App* app, std::string, CLI::AppFormatMode mode) const override
  {
    return this->Usage + "\n\n" + app->get_description() + "\n" + this->make_positionals(app) +
      this->make_groups(app, mode) + "\n" + this->make_footer(app);
  }

private:
  std::string Usage;
};

/**
 * The arguments as App::parse() wants them (in reverse order, without the program). A long
 * option that takes one value is joined to a next argument that starts with '-'
 * ("--view=-Y"), which CLI11 would take for an option, so that a value may start with '-'
 * as it always could; such an option at the end, or followed by another option (a value
 * forgotten: "--stats --quiet"), is an error.
 */
std::vector<std::string> Arguments(const CLI::App& app, int argc, char* argv[])
{
  std::vector<std::string> args;
  for (int i = 1; i < argc; ++i)
  {
    std::string arg = argv[i];
    const bool bareLong =
      arg.size() > 2 && arg.compare(0, 2, "--") == 0 && arg.find('=') == std::string::npos;
    const CLI::Option* option = bareLong ? app.get_option_no_throw(arg) : nullptr;
    if (option && option->get_items_expected_max() == 1)
    {
      // Its value may start with '-' (a negative number, "-1%"), but is never another option.
      if (i + 1 == argc || (argv[i + 1][0] == '-' && app.get_option_no_throw(argv[i + 1])))
      {
        throw UsageError("option " + arg + " needs a value");
      }
      if (argv[i + 1][0] == '-')
      {
        arg += "=" + std::string(argv[++i]);
      }
    }
    args.push_back(arg);
  }
  std::reverse(args.begin(), args.end());
  return args;
}

/// The message of a parse error: the tools' own wording for an unknown option or an
/// argument too many, CLI11's otherwise.
std::string Message(const CLI::App& app, const CLI::ParseError& error)
{
  if (dynamic_cast<const CLI::ExtrasError*>(&error))
  {
    const std::vector<std::string> extra = app.remaining();
    if (!extra.empty() && extra.front().size() > 1 && extra.front()[0] == '-')
    {
      return "unknown option '" + extra.front().substr(0, extra.front().find('=')) + "'";
    }
    if (!extra.empty())
    {
      std::string expected;
      for (const CLI::Option* positional :
           app.get_options([](const CLI::Option* option) { return option->get_positional(); }))
      {
        expected += (expected.empty() ? "" : " ") + positional->get_name();
      }
      return "too many arguments: '" + extra.front() + "' (expected " + expected + ")";
    }
  }
  return error.what();
}
} // namespace

Complaint RuleComplaint(const std::string& rule)
{
  return [rule](const std::string& text) { return rule + " (got '" + text + "')"; };
}

Complaint BadValueComplaint(const std::string& name)
{
  return [name](const std::string& text) { return "bad value '" + text + "' for " + name; };
}

Complaint FixedComplaint(const std::string& message)
{
  return [message](const std::string&) { return message; };
}

void SetUpCommandLine(CLI::App& app, const std::string& usage)
{
  app.formatter(std::make_shared<ToolFormatter>(usage));
  app.get_formatter()->column_width(26);
  app.set_help_flag("-h,--help", "show this help");
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
}

int ReportUsageError(const CLI::App& app, const std::string& message, int usageStatus)
{
  std::cerr << app.get_name() << ": " << message << "\nTry '" << app.get_name() << " --help'."
            << std::endl;
  return usageStatus;
}

int ParseCommandLine(CLI::App& app, int argc, char* argv[], int usageStatus)
{
  try
  {
    app.parse(Arguments(app, argc, argv));
  }
  catch (const CLI::CallForHelp&)
  {
    std::cout << app.help();
    return 0;
  }
  catch (const CLI::ParseError& error)
  {
    return ReportUsageError(app, Message(app, error), usageStatus);
  }
  return -1;
}

bool ParseNumber(const std::string& text, double& value)
{
  if (text.empty())
  {
    return false;
  }
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(value);
}

bool ParseWholeNumber(const std::string& text, long long& value)
{
  if (text.empty())
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  value = std::strtoll(text.c_str(), &end, 10);
  return end == text.c_str() + text.size() && errno != ERANGE;
}

bool ParseCount(const std::string& text, long long& value)
{
  std::string digits = text;
  double scale = 1;
  if (!digits.empty() && (digits.back() == 'k' || digits.back() == 'K'))
  {
    scale = 1e3;
    digits.pop_back();
  }
  else if (!digits.empty() && (digits.back() == 'm' || digits.back() == 'M'))
  {
    scale = 1e6;
    digits.pop_back();
  }
  double number = 0;
  if (digits.empty() || !ParseNumber(digits, number) || number < 0 || number * scale > 1e10)
  {
    return false;
  }
  value = static_cast<long long>(std::llround(number * scale));
  return true;
}

CLI::Option* AddValue(CLI::App& app, const std::string& name,
                      std::function<bool(const std::string&)> apply, Complaint complaint,
                      const std::string& help)
{
  auto check = [apply, complaint](const std::string& text)
  {
    if (!apply(text))
    {
      throw UsageError(complaint(text));
    }
  };
  return app.add_option_function<std::string>(name, check, help);
}

CLI::Option* AddNumber(CLI::App& app, const std::string& name, double& value, double lo, double hi,
                       Complaint complaint, const std::string& help)
{
  auto apply = [&value, lo, hi](const std::string& text)
  {
    double number = 0;
    if (!ParseNumber(text, number) || number < lo || number > hi)
    {
      return false;
    }
    value = number;
    return true;
  };
  return AddValue(app, name, apply, std::move(complaint), help);
}

} // namespace tools
} // namespace colordecimation
