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
  std::string items;
  for (char ch : rest.substr(1, rest.size() - 2)) {
    if (ch == ',') ch = ' ';
    if (ch == ' ' && !items.empty() && items.back() == '=') continue;
    if (ch == '=' && !items.empty() && items.back() == ' ') items.pop_back();
    items += ch;
  }
  for (size_t at = 0; at < items.size();) {
    const size_t begin = items.find_first_not_of(' ', at);
    if (begin == std::string::npos) break;
    const size_t end = std::min(items.find(' ', begin), items.size());
    const std::string item = items.substr(begin, end - begin);
    const size_t eq = item.find('=');
    if (eq == 0) throw LineError{command + ": '=' without a parameter name"};
    out.parameters.push_back(eq == std::string::npos ? CommandParameter{item, std::nullopt}
                                                     : CommandParameter{item.substr(0, eq), item.substr(eq + 1)});
    at = end;
  }
  return out;
}

}  // namespace hil::cnc::decoding
