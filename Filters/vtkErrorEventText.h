// SPDX-License-Identifier: GPL-3.0-or-later
// The message of a VTK ErrorEvent, for re-reporting it in one's own words.
// Private to the module and its tools: not wrapped.
#ifndef vtkErrorEventText_h
#define vtkErrorEventText_h

#include <string>

namespace medialaxis
{
/// VTK's ErrorEvent text is "ERROR: In <file>, line <n>\n<class> (<address>):
/// <message>\n\n": returns <message>.
inline std::string ErrorEventMessage(const void* callData)
{
  std::string text = callData ? static_cast<const char*>(callData) : "unknown error";
  const std::size_t start = text.find("): ");
  text = start == std::string::npos ? text : text.substr(start + 3);
  while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
  {
    text.pop_back();
  }
  return text;
}
}

#endif
