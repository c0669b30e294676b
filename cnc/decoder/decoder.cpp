#include "decoder.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "coordinate_system.hpp"
#include "parameter_expression.hpp"

namespace hil::cnc {
namespace {

struct Word {
  char letter;
  double value;
  std::string text;  // as written, for messages
};

// Thrown inside decoding of one line; turned into the Event of that line.
struct LineError {
  std::string message;
};

std::string strip_comments(const std::string& line) {
  std::string out;
  bool in_paren = false;
  for (char c : line) {
    if (in_paren) {
      if (c == ')') in_paren = false;
      continue;
    }
    if (c == ';') break;
    if (c == '(') {
      in_paren = true;
      continue;
    }
    out += c;
  }
  if (in_paren) throw LineError{"comment '(' is not closed on this line"};
  return out;
}

// A '#' or '$' command the decoder does not know, starting at code[i].
LineError unsupported_command(const std::string& code, size_t i) {
  const size_t end = code.find_first_of(" \t[", i);
  return LineError{"command '" + code.substr(i, end - i) + "' is not supported yet"};
}

std::vector<Word> split_words(const std::string& code) {
  std::vector<Word> words;
  size_t i = 0;
  while (i < code.size()) {
    const unsigned char c = static_cast<unsigned char>(code[i]);
    if (std::isspace(c)) {
      ++i;
      continue;
    }
    if (c == '#' || c == '$') throw unsupported_command(code, i);
    if (!std::isalpha(c)) throw LineError{std::string("unexpected character '") + code[i] + "'"};
    const char letter = static_cast<char>(std::toupper(c));
    size_t j = i + 1;
    while (j < code.size() && (code[j] == ' ' || code[j] == '\t')) ++j;
    const size_t number_start = j;
    if (j < code.size() && (code[j] == '+' || code[j] == '-')) ++j;
    bool digits = false;
    while (j < code.size() && (std::isdigit(static_cast<unsigned char>(code[j])) || code[j] == '.')) {
      digits = digits || code[j] != '.';
      ++j;
    }
    const std::string number = code.substr(number_start, j - number_start);
    if (!digits) throw LineError{std::string("address '") + letter + "' needs a number"};
    char* parse_end = nullptr;
    const double value = std::strtod(number.c_str(), &parse_end);
    if (parse_end != number.c_str() + number.size() || !std::isfinite(value))
      throw LineError{std::string("malformed number '") + number + "' after '" + letter + "'"};
    words.push_back({letter, value, std::string(1, letter) + number});
    i = j;
  }
  return words;
}

int integer_code(const Word& w) {
  if (w.value != std::floor(w.value) || w.value < 0)
    throw LineError{"'" + w.text + "' needs a whole non-negative number"};
  return static_cast<int>(w.value);
}

struct ModalState {
  MotionType motion = MotionType::linear;
  bool absolute = true;   // G90
  double feed = 0;        // mm/s
  SlopeType slope = SlopeType::trapez;
  bool centre_absolute = false;    // G161; G162 (relative to the start) is the initial state
  bool centre_correction = false;  // G165: move the centre onto the circle through start and end; G164 off
};

std::string upper_words(const std::string& text) {
  std::istringstream in(text);
  std::string word, out;
  while (in >> word) {
    for (char& c : word) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    out += (out.empty() ? "" : " ") + word;
  }
  return out;
}

class LineDecoder {
 public:
  LineDecoder(const MachineConfig& machine, std::vector<double> position)
      : machine_(machine), position_(std::move(position)) {}

  const ParameterValues& parameters() const { return parameters_; }
  void set_parameter(int n, double value) { parameters_[n] = value; }

  // Returns false once M30 ended the program.
  bool decode(const std::string& raw, int64_t line_nr, int64_t lines_read, std::vector<Block>& out) {
    std::string code = strip_comments(raw);
    const size_t first = code.find_first_not_of(" \t\r");
    if (first == std::string::npos) return true;
    if (code[first] == '%') return true;  // program name
    Block block;
    block.nc_line = line_nr;
    block.block_count = lines_read;
    const size_t hash = code.find('#');
    if (hash != std::string::npos) {
      // A '#' command is the whole block, after an optional N number.
      const std::vector<Word> before = split_words(code.substr(0, hash));
      if (before.size() > 1 || (before.size() == 1 && before[0].letter != 'N'))
        throw LineError{"a '#' command must stand alone in its block (after the N number)"};
      if (!before.empty()) block.block_nr = integer_code(before[0]);
      decode_command(upper_words(code.substr(hash)), block);
      if (block.has_command()) out.push_back(block);
      return true;
    }
    if (const size_t dollar = code.find('$'); dollar != std::string::npos) throw unsupported_command(code, dollar);
    if (const size_t equals = code.find('='); equals != std::string::npos) {
      assign_parameter(code, equals, block);
      return true;
    }
    const std::vector<Word> words = split_words(code);

    std::vector<std::optional<double>> axis_words(machine_.axes.size());
    std::optional<double> i_word, j_word;
    std::optional<MotionType> motion;
    bool seen_motion_word = false;
    bool set_offset = false;  // G92: the axis words name the current position

    for (size_t k = 0; k < words.size(); ++k) {
      const Word& w = words[k];
      switch (w.letter) {
        case 'N':
          if (k != 0) throw LineError{"'" + w.text + "' must be the first word of the block"};
          block.block_nr = integer_code(w);
          break;
        case 'G': {
          const int g = integer_code(w);
          if (g <= 3) {
            if (seen_motion_word) throw LineError{"two motion G codes in one block"};
            seen_motion_word = true;
            motion = static_cast<MotionType>(g);
          } else if (g == 90) {
            modal_.absolute = true;
          } else if (g == 91) {
            modal_.absolute = false;
          } else if (g == 92) {
            set_offset = true;
          } else if (g == 161 || g == 162) {
            modal_.centre_absolute = g == 161;
          } else if (g == 164 || g == 165) {
            modal_.centre_correction = g == 165;
          } else {
            throw LineError{"G code '" + w.text + "' is not supported yet"};
          }
          break;
        }
        case 'F':
          if (!(w.value > 0)) throw LineError{"feed '" + w.text + "' must be > 0"};
          modal_.feed = w.value / 60.0;
          break;
        case 'M':
          if (integer_code(w) == 30) block.program_end = true;
          else block.m_functions.push_back({integer_code(w), pre_output_mm(integer_code(w))});
          break;
        case 'I': i_word = w.value; break;
        case 'J': j_word = w.value; break;
        default: {
          const int axis = machine_.axis_index(std::string(1, w.letter));
          if (axis < 0) throw LineError{"'" + w.text + "': " + w.letter + " is not an axis of this machine"};
          if (axis_words[axis]) throw LineError{std::string("axis ") + w.letter + " programmed twice"};
          axis_words[axis] = w.value;
        }
      }
    }
    if (set_offset) {
      if (seen_motion_word || i_word || j_word) throw LineError{"G92 must not be combined with motion"};
      if (cs_) throw LineError{"G92 while a #CS is active is not supported yet"};
      for (size_t a = 0; a < axis_words.size(); ++a)
        if (axis_words[a]) offset_[a] = position_[a] - *axis_words[a];
      return true;
    }
    if (motion) modal_.motion = *motion;

    const std::vector<double> target = programmed_target(axis_words);
    bool moves = target != position_;
    const bool is_arc = modal_.motion == MotionType::arc_cw || modal_.motion == MotionType::arc_ccw;
    if ((i_word || j_word) && !is_arc) throw LineError{"I/J are only allowed with G02/G03"};
    if (is_arc && (i_word || j_word)) moves = true;  // full circle: end = start

    if (moves) {
      block.has_motion = true;
      Motion& m = block.motion;
      m.type = modal_.motion;
      m.start = position_;
      m.end = target;
      block.slope = modal_.slope;
      if (m.type != MotionType::rapid) {
        if (!(modal_.feed > 0)) throw LineError{"no feed F programmed for G01/G02/G03"};
        m.feed = modal_.feed;
      }
      if (is_arc) set_arc_centre(m, i_word, j_word);
      position_ = target;
    }
    if (block.has_motion || block.has_command()) out.push_back(block);
    return !block.program_end;
  }

 private:
  // `command` in upper case with single spaces, starting with '#'.
  void decode_command(const std::string& command, Block& block) {
    if (command == "#DISTANCE PROG START ON") block.distance_prog_start = DistanceProgStart::on;
    else if (command == "#DISTANCE PROG START OFF") block.distance_prog_start = DistanceProgStart::off;
    else if (command == "#DISTANCE PROG START CLEAR") block.distance_prog_start = DistanceProgStart::clear;
    else if (command.rfind("#DISTANCE PROG START", 0) == 0)
      throw LineError{"#DISTANCE PROG START needs ON, OFF or CLEAR"};
    else if (command.rfind("#SLOPE", 0) == 0) decode_slope(command);
    else if (command.rfind("#DEL DIST2GO", 0) == 0) block.ddtg_end_marker = decode_end_marker(command);
    else if (command.rfind("#TIME", 0) == 0) block.dwell_s = decode_dwell(command);
    else if (command.rfind("#CS ", 0) == 0) decode_coordinate_system(command, block);
    else if (command.rfind("#CHANNEL INIT", 0) == 0) decode_channel_init(command, block);
    else throw LineError{"command '" + command.substr(0, command.find_first_of(" [")) + "' is not supported yet"};
  }

  // #CHANNEL INIT [CMDPOS]: the command positions the interpolator would
  // report are the ones decoded (this rig has no manual mode offsets); the
  // path stands still there (Block::stops_path).
  static void decode_channel_init(const std::string& command, Block& block) {
    std::string args = command.substr(13);
    args.erase(std::remove(args.begin(), args.end(), ' '), args.end());
    if (args != "[CMDPOS]")
      throw LineError{"#CHANNEL INIT takes [CMDPOS] (ACTPOS and single axes are not supported yet)"};
    block.short_cut_restriction = ShortCutRestriction::channel_initialisation;
  }

  // #CS ON [v1,v2,v3,φ1,φ2,φ3], #CS ON [<id>] [..], #CS OFF; one CS at a time.
  void decode_coordinate_system(const std::string& command, Block& block) {
    block.short_cut_restriction = ShortCutRestriction::not_skippable;  // DDTG-8
    if (command == "#CS OFF") {
      if (!cs_) throw LineError{"#CS OFF without an active #CS"};
      cs_.reset();
      return;
    }
    if (command.rfind("#CS ON", 0) != 0) throw LineError{"#CS takes ON [v1,v2,v3,φ1,φ2,φ3] or OFF"};
    std::vector<std::string> groups;
    for (size_t open = command.find('['); open != std::string::npos; open = command.find('[', open + 1)) {
      const size_t close = command.find(']', open);
      if (close == std::string::npos) throw LineError{"#CS ON: '[' is not closed"};
      groups.push_back(command.substr(open + 1, close - open - 1));
    }
    if (groups.empty() || groups.size() > 2)
      throw LineError{"#CS ON needs [v1,v2,v3,φ1,φ2,φ3], optionally after [<CS-ID>] (stored CS are not supported yet)"};
    if (cs_) throw LineError{"#CS ON while a #CS is active: deselect it with #CS OFF first (nesting is not supported yet)"};
    for (const char* axis : {"X", "Y", "Z"})
      if (machine_.axis_index(axis) < 0) throw LineError{"#CS needs the main axes X, Y and Z"};
    cs_ = CoordinateSystem::parse(groups.back(), parameters_);
  }

  int main_axis(int k) const { return machine_.axis_index(std::string(1, "XYZ"[k])); }
  // Main axes of a machine position in the active #CS, and back.
  Eigen::Vector3d to_program(const std::vector<double>& machine) const {
    Eigen::Vector3d workpiece;
    for (int k = 0; k < 3; ++k) workpiece[k] = machine[main_axis(k)] - offset_[main_axis(k)];
    return cs_->to_program(workpiece);
  }
  Eigen::Vector3d to_machine(const Eigen::Vector3d& program) const {
    Eigen::Vector3d machine = cs_->to_workpiece(program);
    for (int k = 0; k < 3; ++k) machine[k] += offset_[main_axis(k)];
    return machine;
  }

  // The end point of a block with these axis words (G90/G91, G92, #CS).
  std::vector<double> programmed_target(const std::vector<std::optional<double>>& words) const {
    std::vector<double> target = position_;
    auto programmed = [&](double current, double word) { return modal_.absolute ? word : current + word; };
    for (size_t a = 0; a < words.size(); ++a)
      if (words[a]) target[a] = programmed(position_[a], *words[a]) + (modal_.absolute ? offset_[a] : 0.0);
    if (!cs_) return target;
    // In a #CS one main axis word can move all three main axes.
    Eigen::Vector3d point = to_program(position_);
    for (int k = 0; k < 3; ++k)
      if (words[main_axis(k)]) point[k] = programmed(point[k], *words[main_axis(k)]);
    const Eigen::Vector3d machine = to_machine(point);
    for (int k = 0; k < 3; ++k) {
      const int a = main_axis(k);
      target[a] = std::abs(machine[k] - position_[a]) > 1e-9 ? machine[k] : position_[a];
    }
    return target;
  }

  void decode_slope(const std::string& command) {
    std::string args = command.substr(6);
    args.erase(std::remove(args.begin(), args.end(), ' '), args.end());
    const std::string prefix = "[TYPE=";
    if (args.rfind(prefix, 0) != 0 || args.back() != ']')
      throw LineError{"#SLOPE needs [TYPE=STEP|TRAPEZ|SIN2]"};
    const std::string name = args.substr(prefix.size(), args.size() - prefix.size() - 1);
    const std::optional<SlopeType> type = parse_slope_type(name);
    if (!type) throw LineError{"#SLOPE type '" + name + "' is not one of STEP, TRAPEZ, SIN2"};
    modal_.slope = *type;
  }

  double pre_output_mm(int m) const {
    const auto it = pre_output_mm_.find(m);
    return it == pre_output_mm_.end() ? 0.0 : it->second;
  }

  // P<n> = <expression> (a decoder variable) or
  // V.G.M_FCT[<m>].PRE_OUTP_PATH = <mm> (P-CHAN-00070 for M<m> from here
  // on), after an optional N number.
  void assign_parameter(const std::string& code, size_t equals, Block& block) {
    static const std::regex assignment(
        R"(\s*(?:[Nn](\d+)\s+)?(?:[Pp](\d+)|V\.G\.M_FCT\[\s*(\d+)\s*\]\.PRE_OUTP_PATH)\s*)", std::regex::icase);
    std::smatch match;
    const std::string left = code.substr(0, equals);
    if (!std::regex_match(left, match, assignment))
      throw LineError{"'=' is only allowed in P<n> = <expression> and V.G.M_FCT[<m>].PRE_OUTP_PATH = <mm>"};
    if (match[1].matched) block.block_nr = std::atoll(match[1].str().c_str());
    double value = 0;
    try {
      value = evaluate_expression(code.substr(equals + 1), parameters_);
    } catch (const std::invalid_argument& e) {
      throw LineError{e.what()};
    }
    if (match[2].matched) {
      parameters_[std::atoi(match[2].str().c_str())] = value;
    } else {
      if (value < 0) throw LineError{"PRE_OUTP_PATH must be >= 0 mm"};
      pre_output_mm_[std::atoi(match[3].str().c_str())] = value;
    }
  }

  // #TIME <s>: dwell.
  double decode_dwell(const std::string& command) const {
    const std::string value = command.substr(5);
    try {
      const double seconds = evaluate_expression(value, parameters_);
      if (seconds > 0) return seconds;
    } catch (const std::invalid_argument&) {
    }
    throw LineError{"#TIME needs a dwell time > 0 in s"};
  }

  // #DEL DIST2GO, #DEL DIST2GO [], #DEL DIST2GO [END=<32-bit>]: END as a
  // number or an IEC literal '16#0105' (also 2# and 8#); default 1 (DDTG-5).
  static uint32_t decode_end_marker(const std::string& command) {
    std::string args = command.substr(12);
    args.erase(std::remove(args.begin(), args.end(), ' '), args.end());
    if (args.empty() || args == "[]") return 1;
    const std::string prefix = "[END=";
    if (args.rfind(prefix, 0) != 0 || args.back() != ']')
      throw LineError{"#DEL DIST2GO takes [END=<32-bit mask>], e.g. [END='16#0105']"};
    std::string value = args.substr(prefix.size(), args.size() - prefix.size() - 1);
    if (value.size() >= 2 && value.front() == '\'' && value.back() == '\'') value = value.substr(1, value.size() - 2);
    int base = 10;
    if (const size_t hash = value.find('#'); hash != std::string::npos) {
      base = std::atoi(value.substr(0, hash).c_str());
      value = value.substr(hash + 1);
      if (base != 2 && base != 8 && base != 16) throw LineError{"#DEL DIST2GO END: base must be 2#, 8# or 16#"};
    }
    char* end = nullptr;
    const unsigned long long mask = value.empty() ? 0 : std::strtoull(value.c_str(), &end, base);
    if (value.empty() || *end != '\0' || mask > 0xFFFFFFFFull || value[0] == '-')
      throw LineError{"#DEL DIST2GO END '" + value + "' is not a 32-bit mask"};
    return static_cast<uint32_t>(mask);
  }

  void set_arc_centre(Motion& m, std::optional<double> i, std::optional<double> j) {
    const int x = machine_.axis_index("X"), y = machine_.axis_index("Y");
    if (x < 0 || y < 0) throw LineError{"G02/G03 need axes X and Y (plane G17)"};
    if (!i && !j) throw LineError{"G02/G03 need the centre I/J (R is not supported yet)"};
    if (cs_) {
      if (!cs_->keeps_xy_plane()) throw LineError{"G02/G03 in a #CS rotated out of the XY plane are not supported yet"};
      const Eigen::Vector3d start = to_program(m.start);
      const Eigen::Vector3d centre =
          modal_.centre_absolute ? Eigen::Vector3d(i.value_or(start.x()), j.value_or(start.y()), start.z())
                                 : Eigen::Vector3d(start.x() + i.value_or(0), start.y() + j.value_or(0), start.z());
      const Eigen::Vector3d machine = to_machine(centre);
      m.center_x = machine.x();
      m.center_y = machine.y();
    } else if (modal_.centre_absolute) {  // G161: in program coordinates
      m.center_x = i.value_or(m.start[x] - offset_[x]) + offset_[x];
      m.center_y = j.value_or(m.start[y] - offset_[y]) + offset_[y];
    } else {
      m.center_x = m.start[x] + i.value_or(0);
      m.center_y = m.start[y] + j.value_or(0);
    }
    const double chord_x = m.end[x] - m.start[x], chord_y = m.end[y] - m.start[y];
    const double chord = std::hypot(chord_x, chord_y);
    if (modal_.centre_correction && chord > 1e-9) {
      // G165: the nearest centre on the perpendicular bisector of start and end.
      const double mid_x = (m.start[x] + m.end[x]) / 2, mid_y = (m.start[y] + m.end[y]) / 2;
      const double nx = -chord_y / chord, ny = chord_x / chord;
      const double along = (m.center_x - mid_x) * nx + (m.center_y - mid_y) * ny;
      m.center_x = mid_x + along * nx;
      m.center_y = mid_y + along * ny;
    }
    const double r_start = std::hypot(m.start[x] - m.center_x, m.start[y] - m.center_y);
    const double r_end = std::hypot(m.end[x] - m.center_x, m.end[y] - m.center_y);
    if (r_start < 1e-6) throw LineError{"arc radius is zero"};
    if (std::abs(r_start - r_end) > 1e-3 + 1e-6 * r_start) {
      std::ostringstream msg;
      msg << "arc end point does not lie on the circle (start radius " << r_start
          << " mm, end radius " << r_end << " mm; G165 corrects the centre)";
      throw LineError{msg.str()};
    }
  }

  const MachineConfig& machine_;
  std::vector<double> position_;             // machine coordinates
  ParameterValues parameters_;               // P parameters
  std::map<int, double> pre_output_mm_ = machine_.m_pre_output_mm;  // M function pre-output, mm
  std::vector<double> offset_ = std::vector<double>(position_.size(), 0.0);  // G92: machine - program
  std::optional<CoordinateSystem> cs_;       // #CS ON
  ModalState modal_;
};

}  // namespace

namespace {

Event line_error(const std::string& message, const std::string& line, int64_t line_nr) {
  Event error;
  error.severity = Severity::error;
  error.nc_line = line_nr;
  // The N number if the line starts with one, for the message.
  const size_t n = line.find_first_not_of(" \t");
  if (n != std::string::npos && (line[n] == 'N' || line[n] == 'n')) error.block_nr = std::atoll(line.c_str() + n + 1);
  error.message = message + " in '" + line + "'";
  return error;
}

// $FOR P<n> = <start>, <end> [, <step>] ... $ENDFOR: the lines between run
// while P<n> has not passed <end> (KRN-1).
struct Loop {
  size_t first_line;  // the line after $FOR
  int parameter;
  double end;
  double step;
  bool done(double value) const { return step > 0 ? value > end + 1e-9 : value < end - 1e-9; }
};

const std::regex for_line(R"(\s*(?:[Nn]\d+\s+)?\$FOR\s+[Pp](\d+)\s*=\s*([^,]+),([^,]+)(?:,([^,]+))?\s*)",
                          std::regex::icase);
const std::regex endfor_line(R"(\s*(?:[Nn]\d+\s+)?\$ENDFOR\s*)", std::regex::icase);

// The line after the $ENDFOR that closes the $FOR at `line`, or none.
std::optional<size_t> after_endfor(const std::vector<std::string_view>& lines, size_t line) {
  int depth = 0;
  for (size_t i = line; i < lines.size(); ++i) {
    if (lines[i].find('$') == std::string_view::npos) continue;
    const std::string code = strip_comments(std::string(lines[i]));
    if (std::regex_match(code, for_line)) ++depth;
    if (std::regex_match(code, endfor_line) && --depth == 0) return i + 1;
  }
  return std::nullopt;
}

constexpr int64_t max_lines_read = 10000000;  // an endless loop is an error, not a hang

}  // namespace

DecodedProgram decode_program(const std::string& text, const MachineConfig& machine,
                              const std::vector<double>& start) {
  DecodedProgram program;
  LineDecoder decoder(machine, start);
  // Views into `text`: $FOR loops read lines again.
  std::vector<std::string_view> lines;
  for (size_t begin = 0; begin < text.size();) {
    const size_t end = std::min(text.find('\n', begin), text.size());
    lines.emplace_back(text.data() + begin, end - begin);
    begin = end + 1;
  }
  std::vector<Loop> loops;
  int64_t lines_read = 0;
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string line(lines[i]);
    try {
      if (++lines_read > max_lines_read)
        throw LineError{"more than " + std::to_string(max_lines_read) + " lines read: endless $FOR loop?"};
      // Plain blocks (no '$') spare the loop regexes.
      const bool control_flow = line.find('$') != std::string::npos;
      const std::string code = control_flow ? strip_comments(line) : std::string();
      std::smatch m;
      if (control_flow && std::regex_match(code, m, for_line)) {
        auto value = [&](const std::ssub_match& part) { return evaluate_expression(part.str(), decoder.parameters()); };
        Loop loop{i + 1, std::atoi(m[1].str().c_str()), value(m[3]), m[4].matched ? value(m[4]) : 1.0};
        if (loop.step == 0) throw LineError{"$FOR step must not be 0"};
        const std::optional<size_t> next = after_endfor(lines, i);
        if (!next) throw LineError{"$FOR without $ENDFOR"};
        const double first = value(m[2]);
        decoder.set_parameter(loop.parameter, first);
        if (loop.done(first)) i = *next - 1;
        else loops.push_back(loop);
        continue;
      }
      if (control_flow && std::regex_match(code, endfor_line)) {
        if (loops.empty()) throw LineError{"$ENDFOR without $FOR"};
        const Loop& loop = loops.back();
        const double value = decoder.parameters().at(loop.parameter) + loop.step;
        decoder.set_parameter(loop.parameter, value);
        if (loop.done(value)) loops.pop_back();
        else i = loop.first_line - 1;
        continue;
      }
      if (!decoder.decode(line, static_cast<int64_t>(i) + 1, lines_read, program.blocks)) break;
    } catch (const LineError& e) {
      program.error = line_error(e.message, line, static_cast<int64_t>(i) + 1);
      break;
    } catch (const std::invalid_argument& e) {
      program.error = line_error(e.what(), line, static_cast<int64_t>(i) + 1);
      break;
    }
  }
  return program;
}

}  // namespace hil::cnc
