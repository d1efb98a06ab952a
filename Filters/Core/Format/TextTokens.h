// SPDX-License-Identifier: GPL-3.0-or-later
// Locale-independent tokenising and number parsing for the text formats
// (.ma, OFF). std::from_chars never reads past the token and never depends on
// the process locale, unlike strtod/iostreams.
#ifndef medialaxis_TextTokens_h
#define medialaxis_TextTokens_h

#include <charconv>
#include <cstdint>
#include <string_view>
#include <vector>

namespace medialaxis
{
/// Splits a line at blanks, dropping everything from the first '#'.
inline std::vector<std::string_view> SplitTokens(std::string_view line)
{
  std::vector<std::string_view> tokens;
  const std::size_t hash = line.find('#');
  if (hash != std::string_view::npos)
  {
    line = line.substr(0, hash);
  }
  std::size_t i = 0;
  while (i < line.size())
  {
    while (i < line.size() &&
      (line[i] == ' ' || line[i] == '\t' || line[i] == '\r' || line[i] == '\f' || line[i] == '\v'))
    {
      ++i;
    }
    std::size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r' &&
      line[j] != '\f' && line[j] != '\v')
    {
      ++j;
    }
    if (j > i)
    {
      tokens.push_back(line.substr(i, j - i));
    }
    i = j;
  }
  return tokens;
}

/// Whole-token parse of a double; "nan"/"inf" parse (callers decide).
inline bool ParseDouble(std::string_view token, double& value)
{
  if (!token.empty() && token.front() == '+')
  {
    token.remove_prefix(1);
  }
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, value);
  return result.ec == std::errc() && result.ptr == end;
}

/// Whole-token parse of a signed 64-bit integer.
inline bool ParseInteger(std::string_view token, std::int64_t& value)
{
  if (!token.empty() && token.front() == '+')
  {
    token.remove_prefix(1);
  }
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, value);
  return result.ec == std::errc() && result.ptr == end;
}
}

#endif
