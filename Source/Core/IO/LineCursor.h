// A cursor over the lines and words of a text held in memory, with line-numbered errors.
#pragma once

#include "Error.h"

#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace kerf
{

/// Walks a text line by line and each line word by word, skipping blank lines (and comments when
/// a comment character is given). Numbers are parsed with std::from_chars, so "nan" and "inf"
/// read as such and a word is a number only if all of it is. Errors name the line:
/// "<kind> line <n>: <message>".
class LineCursor
{
public:
  LineCursor(std::string_view text, std::string kind, char comment = '#')
    : Text(text)
    , Kind(std::move(kind))
    , Comment(comment)
  {
  }

  /// Moves to the next line with content; false at the end of the text.
  bool next()
  {
    while (this->Position < this->Text.size())
    {
      const std::size_t end = this->Text.find('\n', this->Position);
      const std::size_t stop = end == std::string_view::npos ? this->Text.size() : end;
      this->First = this->Text.data() + this->Position;
      this->Last = this->Text.data() + stop;
      this->Position = stop == this->Text.size() ? stop : stop + 1;
      ++this->LineNumber;
      if (this->Comment != '\0')
      {
        for (const char* c = this->First; c != this->Last; ++c)
        {
          if (*c == this->Comment)
          {
            this->Last = c;
            break;
          }
        }
      }
      this->skipSpace();
      if (this->First != this->Last)
      {
        return true;
      }
    }
    this->First = this->Last = this->Text.data() + this->Text.size();
    return false;
  }

  bool atEndOfLine()
  {
    this->skipSpace();
    return this->First == this->Last;
  }

  /// The next word of the current line ("" at its end).
  std::string_view word()
  {
    this->skipSpace();
    const char* start = this->First;
    while (this->First != this->Last && !isSpace(*this->First))
    {
      ++this->First;
    }
    return std::string_view(start, static_cast<std::size_t>(this->First - start));
  }

  /// The next word, moving on to later lines when this one is used up ("" at the end of the text).
  std::string_view wordAcrossLines()
  {
    while (this->atEndOfLine())
    {
      if (!this->next())
      {
        return std::string_view();
      }
    }
    return this->word();
  }

  /// True if the next word is an integer (digits with an optional sign).
  bool startsWithInteger()
  {
    this->skipSpace();
    const char* c = this->First;
    if (c != this->Last && (*c == '-' || *c == '+'))
    {
      ++c;
    }
    const char* digits = c;
    while (c != this->Last && *c >= '0' && *c <= '9')
    {
      ++c;
    }
    return c != digits && (c == this->Last || isSpace(*c));
  }

  long long integer(const char* what)
  {
    long long value = 0;
    if (!parseInteger(this->word(), value))
    {
      this->fail(std::string("expected an integer (") + what + ")");
    }
    return value;
  }

  double real(const char* what)
  {
    double value = 0.0;
    if (!parseReal(this->word(), value))
    {
      this->fail(std::string("expected a number (") + what + ")");
    }
    return value;
  }

  /// Parses all of text as a decimal integer (an optional sign, then digits).
  static bool parseInteger(std::string_view text, long long& value)
  {
    if (!text.empty() && text.front() == '+')
    {
      text.remove_prefix(1);
    }
    const std::from_chars_result r = std::from_chars(text.data(), text.data() + text.size(), value);
    return !text.empty() && r.ec == std::errc() && r.ptr == text.data() + text.size();
  }

  /// Parses all of text as a real number; literals beyond double's range read as infinities or
  /// zero (validation decides what to do with them).
  static bool parseReal(std::string_view text, double& value)
  {
    if (!text.empty() && text.front() == '+')
    {
      text.remove_prefix(1);
    }
    const char* end = text.data() + text.size();
    const std::from_chars_result r = std::from_chars(text.data(), end, value);
    if (text.empty() || r.ptr != end)
    {
      return false;
    }
    if (r.ec == std::errc::result_out_of_range)
    {
      value = std::strtod(std::string(text).c_str(), nullptr);
      return true;
    }
    return r.ec == std::errc();
  }

  [[noreturn]] void fail(const std::string& message) const
  {
    throw Error(this->Kind + " line " + std::to_string(this->LineNumber) + ": " + message);
  }

  int line() const { return this->LineNumber; }
  /// Byte offset of the cursor in the text.
  std::size_t offset() const { return static_cast<std::size_t>(this->First - this->Text.data()); }
  /// Byte offset just past the current line's newline (or the end of the text).
  std::size_t nextLineOffset() const { return this->Position; }
  /// The unread rest of the current line.
  std::string_view rest() const
  {
    return std::string_view(this->First, static_cast<std::size_t>(this->Last - this->First));
  }
  /// Continues at byte offset `offset`, the start of a line, counting `lines` lines passed.
  void jump(std::size_t offset, int lines)
  {
    this->Position = offset;
    this->LineNumber += lines;
    this->First = this->Last = this->Text.data() + offset;
  }

  static bool isSpace(char c) { return c == ' ' || (c >= '\t' && c <= '\r'); }

private:
  void skipSpace()
  {
    while (this->First != this->Last && isSpace(*this->First))
    {
      ++this->First;
    }
  }

  std::string_view Text;
  std::string Kind;
  char Comment;
  std::size_t Position = 0;
  int LineNumber = 0;
  const char* First = nullptr;
  const char* Last = nullptr;
};

/// The word of `text` at or after `position` (moved past it), or "" when only blanks remain.
inline std::string_view nextWord(std::string_view text, std::size_t& position)
{
  while (position < text.size() && LineCursor::isSpace(text[position]))
  {
    ++position;
  }
  const std::size_t start = position;
  while (position < text.size() && !LineCursor::isSpace(text[position]))
  {
    ++position;
  }
  return text.substr(start, position - start);
}

/// The whitespace-separated words of a line.
inline std::vector<std::string_view> splitWords(std::string_view line)
{
  std::vector<std::string_view> words;
  std::size_t position = 0;
  for (std::string_view w = nextWord(line, position); !w.empty(); w = nextWord(line, position))
  {
    words.push_back(w);
  }
  return words;
}

/// `text` in single quotes for an error message: at most 40 characters, control and non-ASCII
/// bytes shown as '?'.
inline std::string quoted(std::string_view text)
{
  std::string out = "'";
  for (std::size_t i = 0; i < text.size() && i < 40; ++i)
  {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    out += c >= 32 && c < 127 ? static_cast<char>(c) : '?';
  }
  return out + (text.size() > 40 ? "...'" : "'");
}

} // namespace kerf
