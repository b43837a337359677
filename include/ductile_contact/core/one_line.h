#pragma once

#include <cctype>
#include <string>

namespace DuctileContact
{
  /// @p text with every run of white space (line breaks included) replaced
  /// by one blank and none at the start: library messages (deal.II's carry
  /// a banner and line breaks) fit the one line a message has on screen.
  inline std::string
  one_line(const std::string &text)
  {
    std::string out;
    for (const char c : text)
      if (!std::isspace(static_cast<unsigned char>(c)))
        out += c;
      else if (!out.empty() && out.back() != ' ')
        out += ' ';
    if (!out.empty() && out.back() == ' ')
      out.pop_back();
    return out;
  }
} // namespace DuctileContact
