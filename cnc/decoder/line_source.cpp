#include "line_source.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

namespace hil::cnc {

bool StringLines::next_line(std::string_view& line) {
  if (pos_ >= text_.size()) return false;
  const size_t end = std::min(text_.find('\n', pos_), text_.size());
  line = text_.substr(pos_, end - pos_);
  pos_ = end + 1;
  return true;
}

bool StreamLines::next_line(std::string_view& line) {
  if (!in_ || !std::getline(*in_, buffer_)) return false;
  line = buffer_;
  return true;
}

ProgramText program_text(std::string text) {
  auto shared = std::make_shared<const std::string>(std::move(text));
  return [shared] { return std::unique_ptr<LineSource>(std::make_unique<StringLines>(*shared, shared)); };
}

ProgramText program_file(std::string path) {
  return [path] {
    return std::unique_ptr<LineSource>(std::make_unique<StreamLines>(std::make_unique<std::ifstream>(path)));
  };
}

bool LineStore::has(size_t i) {
  while (i >= first_ + held()) {
    std::string_view line;
    if (ended_ || !source_.next_line(line)) {
      ended_ = true;
      return false;
    }
    spans_.push_back({chars_.size(), line.size()});
    chars_.append(line);
  }
  return i >= first_;
}

void LineStore::forget_before(size_t i) {
  if (i <= first_) return;
  const size_t n = std::min(i - first_, held());
  head_ += n;
  first_ += n;
  if (head_ == spans_.size()) {  // nothing held: start over (the usual case, no loop open)
    spans_.clear();
    chars_.clear();
    head_ = 0;
    return;
  }
  // Drop the forgotten part in batches: linear in the text read.
  if (head_ < 1024 || head_ < spans_.size() / 2) return;
  const size_t cut = spans_[head_].begin;
  chars_.erase(0, cut);
  spans_.erase(spans_.begin(), spans_.begin() + static_cast<std::ptrdiff_t>(head_));
  for (Span& s : spans_) s.begin -= cut;
  head_ = 0;
}

}  // namespace hil::cnc
