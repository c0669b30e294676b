#pragma once
// The text of an NC program, line by line (issue 17): a program is read as
// it is decoded, never held whole, whether it comes from a file, a stream
// or a string (the rig's scenarios carry theirs inline).
#include <cstddef>
#include <functional>
#include <istream>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hil::cnc {

class LineSource {
 public:
  virtual ~LineSource() = default;
  // The next line without its '\n' into `line` (valid until the next call);
  // false at the end of the text. "a\nb\n" and "a\nb" are both two lines.
  virtual bool next_line(std::string_view& line) = 0;
};

// Lines of a text in memory: `text` lives as long as this, or `owner` keeps it.
class StringLines : public LineSource {
 public:
  explicit StringLines(std::string_view text, std::shared_ptr<const std::string> owner = nullptr)
      : text_(text), owner_(std::move(owner)) {}
  bool next_line(std::string_view& line) override;

 private:
  std::string_view text_;
  std::shared_ptr<const std::string> owner_;
  size_t pos_ = 0;
};

// Lines of a stream (a file), as std::getline splits them. Read in chunks
// and split with memchr: getline took a fifth of a plain block's decoding.
class StreamLines : public LineSource {
 public:
  explicit StreamLines(std::unique_ptr<std::istream> in) : in_(std::move(in)) {}
  bool next_line(std::string_view& line) override;

 private:
  // Reads on into buffer_ behind what is not split yet; false at the end.
  bool read_more();

  std::unique_ptr<std::istream> in_;
  std::string buffer_;  // [begin_, buffer_.size()): read, not handed out yet
  size_t begin_ = 0;
};

// What a program start reads: a new LineSource over the program's text each time.
using ProgramText = std::function<std::unique_ptr<LineSource>()>;
ProgramText program_text(std::string text);
// A file, opened at each program start; one that cannot be opened reads as
// no line (the decoder's end without M30).
ProgramText program_file(std::string path);

// The lines read so far that are still needed ($FOR loops read their body
// again), indexed from 0 for the first line of the text. Holds the lines
// from the oldest one not forgotten up to the furthest one read.
class LineStore {
 public:
  explicit LineStore(LineSource& source) : source_(source) {}
  // Reads on up to line i; false if the text ends before it.
  bool has(size_t i);
  // Line i, read and not forgotten; valid until the next has().
  std::string_view operator[](size_t i) const {
    const Span& s = spans_[head_ + (i - first_)];
    return std::string_view(chars_.data() + s.begin, s.size);
  }
  // Lines below i are not needed any more.
  void forget_before(size_t i);
  // How many lines are held (for the bounds of docs/ARCHITECTURE.md).
  size_t held() const { return spans_.size() - head_; }

 private:
  struct Span {
    size_t begin, size;
  };
  LineSource& source_;
  std::string chars_;
  std::vector<Span> spans_;  // from head_ on: lines first_, first_ + 1, ..
  size_t head_ = 0;          // spans before it are forgotten (dropped in batches)
  size_t first_ = 0;
  bool ended_ = false;
};

}  // namespace hil::cnc
