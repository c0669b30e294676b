#include "command_parameters.hpp"

#include <algorithm>
#include <utility>

#include "words.hpp"

namespace hil::cnc::decoding {
namespace {

// ON / OFF as a word of its own at the start of `rest`, which it then leaves.
std::optional<bool> take_switch(std::string& rest) {
  for (const auto& [word, on] : {std::pair<const char*, bool>{"ON", true}, {"OFF", false}}) {
    const std::string w = word;
    if (rest.rfind(w, 0) == 0 && (rest.size() == w.size() || rest[w.size()] == ' ' || rest[w.size()] == '[')) {
      rest.erase(0, w.size());
      return on;
    }
  }
  return std::nullopt;
}

}  // namespace

CommandArguments read_command_arguments(const std::string& command, const std::string& arguments) {
  CommandArguments out;
  std::string rest = arguments;
  out.on = take_switch(rest);
  const size_t first = rest.find_first_not_of(' ');
  rest = first == std::string::npos ? "" : rest.substr(first);
  if (rest.empty()) return out;
  if (rest.front() != '[' || rest.back() != ']' || rest.find(']') != rest.size() - 1)
    throw LineError{command + ": parameters go in one [..], not '" + rest + "'"};
  out.has_list = true;
  std::string items = rest.substr(1, rest.size() - 2);
  std::replace(items.begin(), items.end(), ',', ' ');
  out.parameters = read_parameter_items(command, items);
  return out;
}

std::vector<CommandParameter> read_parameter_items(const std::string& command, const std::string& items) {
  // Blanks around '=' dropped; a blank inside brackets marked so that it
  // does not separate.
  constexpr char kept_blank = '\x01';
  std::string text;
  int depth = 0;
  for (const char c : items) {
    if (c == '[') ++depth;
    if (c == ']') --depth;
    if (depth == 0 && c == ' ' && !text.empty() && text.back() == '=') continue;
    if (depth == 0 && c == '=' && !text.empty() && text.back() == ' ') text.pop_back();
    text += c == ' ' && depth > 0 ? kept_blank : c;
  }
  std::vector<CommandParameter> parameters;
  for (size_t at = 0; at < text.size();) {
    const size_t begin = text.find_first_not_of(' ', at);
    if (begin == std::string::npos) break;
    const size_t end = std::min(text.find(' ', begin), text.size());
    std::string item = text.substr(begin, end - begin);
    std::replace(item.begin(), item.end(), kept_blank, ' ');
    const size_t eq = item.find('=');
    if (eq == 0) throw LineError{command + ": '=' without a parameter name"};
    parameters.push_back(eq == std::string::npos ? CommandParameter{item, std::nullopt}
                                                 : CommandParameter{item.substr(0, eq), item.substr(eq + 1)});
    at = end;
  }
  return parameters;
}

}  // namespace hil::cnc::decoding
