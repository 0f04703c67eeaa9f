// Parsing and checking the kerf program's command line.
#include "KerfArguments.h"

#include <cmath>
#include <sstream>

namespace kerf
{

namespace
{
// Options that take no value.
const char* const Flags[] = { "help", "quiet", "timings", "no-pictures", "refuse-non-disks", "auto" };

std::string range(double minimum, double maximum)
{
  std::ostringstream text;
  text << minimum << " to " << maximum;
  return text.str();
}
} // namespace

std::string Arguments::get(const std::string& name, const std::string& fallback) const
{
  const auto found = this->options.find(name);
  return found == this->options.end() ? fallback : found->second;
}

double Arguments::number(const std::string& name, double fallback, double minimum, double maximum) const
{
  if (!this->has(name))
  {
    return fallback;
  }
  std::istringstream in(this->get(name));
  double value;
  if (!(in >> value) || !in.eof() || !std::isfinite(value))
  {
    throw CommandError{ "--" + name + " expects a number, got '" + this->get(name) + "'" };
  }
  if (value < minimum || value > maximum)
  {
    throw CommandError{ "--" + name + " expects a number from " + range(minimum, maximum) + ", got '" +
      this->get(name) + "'" };
  }
  return value;
}

int Arguments::integer(const std::string& name, int fallback, int minimum, int maximum) const
{
  const double value = this->number(name, fallback, minimum, maximum);
  if (value != std::floor(value))
  {
    throw CommandError{ "--" + name + " expects a whole number from " + range(minimum, maximum) + ", got '" +
      this->get(name) + "'" };
  }
  return static_cast<int>(value);
}

std::string Arguments::single(const char* what) const
{
  if (this->positional.size() != 1)
  {
    throw CommandError{ std::string("expected one ") + what + " (see --help)" };
  }
  return this->positional[0];
}

Arguments parseArguments(int argc, char* argv[], int first)
{
  Arguments args;
  for (int i = first; i < argc; ++i)
  {
    std::string word = argv[i];
    if (word.size() > 2 && word.compare(0, 2, "--") == 0)
    {
      std::string name = word.substr(2);
      const std::size_t equals = name.find('=');
      if (equals != std::string::npos)
      {
        args.options[name.substr(0, equals)] = name.substr(equals + 1);
        continue;
      }
      bool flag = false;
      for (const char* f : Flags)
      {
        flag = flag || name == f;
      }
      if (flag)
      {
        args.options[name] = "1";
      }
      else if (i + 1 < argc)
      {
        args.options[name] = argv[++i];
      }
      else
      {
        throw CommandError{ "--" + name + " needs a value" };
      }
    }
    else if (word == "-o" && i + 1 < argc)
    {
      args.options["output"] = argv[++i];
    }
    else if (word == "-k" && i + 1 < argc)
    {
      args.options["k"] = argv[++i]; // the number of segments
    }
    else if (word == "-h")
    {
      args.options["help"] = "1";
    }
    else
    {
      args.positional.push_back(word);
    }
  }
  return args;
}

} // namespace kerf
