#include "yaml_error.hpp"

#include <optional>
#include <sstream>
#include <vector>

namespace hil {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

struct Opening {
  char bracket = 0;
  size_t line = 0, column = 0;  // 0-based
};

// The innermost '{' or '[' not closed, skipping quoted text and comments; none
// if every one is closed. A flow collection may span lines, so the scan
// runs over the whole text up to the line after `last`.
std::optional<Opening> unclosed_bracket(const std::vector<std::string>& lines, size_t last) {
  std::vector<Opening> open;
  for (size_t l = 0; l < lines.size() && l <= last; ++l) {
    char quote = 0;
    const std::string& s = lines[l];
    for (size_t c = 0; c < s.size(); ++c) {
      const char ch = s[c];
      if (quote) {
        if (ch == quote) quote = 0;
        continue;
      }
      if (ch == '#' && (c == 0 || s[c - 1] == ' ')) break;
      if ((ch == '"' || ch == '\'') && (c == 0 || std::string(" [{,:").find(s[c - 1]) != std::string::npos)) quote = ch;
      else if (ch == '{' || ch == '[') open.push_back({ch, l, c});
      else if ((ch == '}' || ch == ']') && !open.empty()) open.pop_back();
    }
  }
  if (open.empty()) return std::nullopt;
  return open.back();  // the innermost: its closing bracket is the first one missing
}

std::string shown(const std::vector<std::string>& lines, size_t line, size_t column) {
  if (line >= lines.size()) return "";
  std::string text = lines[line];
  for (char& c : text)
    if (c == '\t') c = ' ';  // the caret lines up
  const std::string number = std::to_string(line + 1);
  return "\n  " + number + " | " + text + "\n  " + std::string(number.size(), ' ') + " | " + std::string(column, ' ') +
         "^";
}

}  // namespace

std::string explain_yaml_error(const std::string& text, const YAML::Exception& error) {
  const std::vector<std::string> lines = lines_of(text);
  const size_t at = error.mark.line < 0 ? 0 : static_cast<size_t>(error.mark.line);
  const size_t column = error.mark.column < 0 ? 0 : static_cast<size_t>(error.mark.column);
  // A TAB where the indentation is, at or before the refused line.
  for (size_t l = 0; l < lines.size() && l <= at + 1; ++l) {
    const size_t content = lines[l].find_first_not_of(" \t");
    const size_t tab = lines[l].find('\t');
    if (tab != std::string::npos && (content == std::string::npos || tab < content))
      return "line " + std::to_string(l + 1) + ": a TAB in the indentation (YAML indents with spaces only)" +
             shown(lines, l, tab);
  }
  const std::string& said = error.msg;
  // A flow collection may span lines: one still open where the parser gave up is the cause.
  if (const std::optional<Opening> open = unclosed_bracket(lines, at))
    return "line " + std::to_string(open->line + 1) + ": the '" + open->bracket + "' opened here is not closed (a '" +
           (open->bracket == '{' ? '}' : ']') + "' is missing before line " + std::to_string(at + 1) + ")" +
           shown(lines, open->line, open->column);
  if (said == "illegal map value" && at < lines.size() && column < lines[at].size() && lines[at][column] == ':' &&
      lines[at].find(": ") < column)
    return "line " + std::to_string(at + 1) + ": a second ': ' in one line (a value holding ': ' goes in quotes)" +
           shown(lines, at, column);
  if (said == "end of map not found" || said == "end of sequence not found" || said == "illegal map value" ||
      said == "block sequence entries are not allowed in this context")
    return "line " + std::to_string(at + 1) +
           ": the indentation does not fit the lines above (a key indented more or less than the keys beside it, "
           "or a list item '- ' beside keys)" +
           shown(lines, at, column);
  if (said.find("block entry") != std::string::npos)  // "illegal block entry", ...
    return "line " + std::to_string(at + 1) + ": a list item '- ' where a key or value belongs (check the indentation)" +
           shown(lines, at, column);
  if (said.find("end of") != std::string::npos && said.find("quoted") != std::string::npos)
    return "line " + std::to_string(at + 1) + ": a quoted text is not closed" + shown(lines, at, column);
  return "line " + std::to_string(at + 1) + " column " + std::to_string(column + 1) + ": " + said +
         shown(lines, at, column);
}

}  // namespace hil
