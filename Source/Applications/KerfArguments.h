// The kerf program's command line: positional arguments, --name value options, checked numbers.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace kerf
{

/// A failure the program reports as "kerf: error: ..." with exit code 1.
struct CommandError
{
  std::string message;
};

/// A parsed command line: positional arguments and --name value options (or --flag).
struct Arguments
{
  std::vector<std::string> positional;
  std::map<std::string, std::string> options;

  bool has(const std::string& name) const { return this->options.count(name) != 0; }
  std::string get(const std::string& name, const std::string& fallback = "") const;
  /// A finite number in [minimum, maximum]; throws CommandError naming the option otherwise.
  double number(const std::string& name, double fallback, double minimum, double maximum) const;
  /// A whole number in [minimum, maximum]; throws CommandError naming the option otherwise.
  int integer(const std::string& name, int fallback, int minimum, int maximum) const;
  /// The only positional argument; throws CommandError if there are none or several.
  std::string single(const char* what) const;
};

/// Parses argv[first..argc); --name=value, --name value, the flags --help, --quiet, --timings,
/// --no-pictures, --refuse-non-disks and --auto, -o FILE (--output) and -h (--help).
Arguments parseArguments(int argc, char* argv[], int first);

} // namespace kerf
