#include "line_source.hpp"

#include <algorithm>
#include <cstring>
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

namespace {
constexpr size_t stream_chunk = 64 * 1024;
}  // namespace

bool StreamLines::read_more() {
  if (!in_ || !*in_) return false;
  buffer_.erase(0, begin_);  // the line handed out last is done with
  begin_ = 0;
  const size_t kept = buffer_.size();
  buffer_.resize(kept + stream_chunk);
  in_->read(buffer_.data() + kept, static_cast<std::streamsize>(stream_chunk));
  buffer_.resize(kept + static_cast<size_t>(in_->gcount()));
  return buffer_.size() > kept;
}

bool StreamLines::next_line(std::string_view& line) {
  size_t searched = begin_;
  for (;;) {
    const void* found = std::memchr(buffer_.data() + searched, '\n', buffer_.size() - searched);
    if (found) {
      const size_t end = static_cast<size_t>(static_cast<const char*>(found) - buffer_.data());
      line = std::string_view(buffer_.data() + begin_, end - begin_);
      begin_ = end + 1;
      return true;
    }
    const size_t searched_chars = buffer_.size() - begin_;
    if (!read_more()) break;
    searched = searched_chars;  // read_more moved the rest to the front
  }
  // The last line without '\n'; none if nothing is left (getline's failbit).
  if (begin_ == buffer_.size()) return false;
  line = std::string_view(buffer_.data() + begin_, buffer_.size() - begin_);
  begin_ = buffer_.size();
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
