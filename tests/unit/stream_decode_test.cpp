// Issue 17 (programs of any length), KRN-1, KRN-2, KRN-5, DDTG-5, DDTG-6,
// DPS-3, LIFT-1, LIFT-5, P-CHAN-00070: the streamed decoder and the stages
// after it (M function pre-output, the lift's preparation) give exactly the
// blocks, ranges and error the whole-program decoding of before gave
// (reference/reference_decoder.cpp, frozen), and hold what they must look
// back on only; the channel holds a bounded number of blocks however long
// its program is.
#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "block_search.hpp"
#include "channel.hpp"
#include "decoder.hpp"
#include "lift_ranges.hpp"
#include "line_source.hpp"
#include "m_pre_output.hpp"
#include "program_decoder.hpp"
#include "program_stream.hpp"
#include "reference/reference_decoder.hpp"
#include "scenario.hpp"
#include "short_cut_target.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;

namespace {

std::string vec(const std::vector<double>& v) {
  std::ostringstream out;
  out.precision(17);
  for (double x : v) out << x << ' ';
  return out.str();
}

// What differs between two blocks, "" if nothing (every field, exactly).
std::string difference(const Block& a, const Block& b) {
  std::ostringstream d;
  auto field = [&](const char* name, bool same) {
    if (!same) d << name << ' ';
  };
  field("nc_line", a.nc_line == b.nc_line);
  field("block_count", a.block_count == b.block_count);
  field("block_nr", a.block_nr == b.block_nr);
  field("has_motion", a.has_motion == b.has_motion);
  field("continues_block", a.continues_block == b.continues_block);
  field("short_cut_restriction", a.short_cut_restriction == b.short_cut_restriction);
  const Motion &m = a.motion, &n = b.motion;
  field("motion.type", m.type == n.type);
  field("motion.start", m.start == n.start);
  field("motion.end", m.end == n.end);
  field("motion.center", m.center[0] == n.center[0] && m.center[1] == n.center[1]);
  field("motion.feed", m.feed == n.feed);
  field("motion.caps", m.path_caps.v == n.path_caps.v && m.path_caps.a == n.path_caps.a && m.path_caps.j == n.path_caps.j);
  field("slope", a.slope == b.slope);
  field("distance_prog_start", a.distance_prog_start == b.distance_prog_start);
  field("ddtg_end_marker", a.ddtg_end_marker == b.ddtg_end_marker);
  field("program_end", a.program_end == b.program_end);
  field("m_functions", a.m_functions == b.m_functions);
  field("dwell_s", a.dwell_s == b.dwell_s);
  field("transition", a.transition == b.transition);
  field("contour", a.contour.type == b.contour.type && a.contour.path_dev == b.contour.path_dev &&
                       a.contour.dist == b.contour.dist);
  field("programmed_stop", a.programmed_stop == b.programmed_stop);
  const bool insert_same =
      a.insert_cmd.has_value() == b.insert_cmd.has_value() &&
      (!a.insert_cmd ||
       (a.insert_cmd->off == b.insert_cmd->off && a.insert_cmd->command.has_value() == b.insert_cmd->command.has_value() &&
        (!a.insert_cmd->command ||
         (a.insert_cmd->command->dist_or_pos == b.insert_cmd->command->dist_or_pos &&
          a.insert_cmd->command->rel_abs_mode == b.insert_cmd->command->rel_abs_mode &&
          a.insert_cmd->command->axis_nr == b.insert_cmd->command->axis_nr &&
          a.insert_cmd->command->m_function_nr == b.insert_cmd->command->m_function_nr &&
          a.insert_cmd->command->add_nr == b.insert_cmd->command->add_nr))));
  field("insert_cmd", insert_same);
  const bool lift_same = a.lift_start.has_value() == b.lift_start.has_value() &&
                         (!a.lift_start || (a.lift_start->axis == b.lift_start->axis &&
                                            a.lift_start->down == b.lift_start->down &&
                                            a.lift_start->pos == b.lift_start->pos &&
                                            a.lift_start->pos_limit == b.lift_start->pos_limit));
  field("lift_start", lift_same);
  field("lift_end", a.lift_end == b.lift_end);
  field("lift_positioning", a.lift_positioning == b.lift_positioning);
  field("not_searchable", a.not_searchable == b.not_searchable);
  if (!d.str().empty()) d << "(line " << a.nc_line << " / " << b.nc_line << ": end " << vec(m.end) << "/ " << vec(n.end) << ")";
  return d.str();
}

std::string difference(const std::optional<Event>& a, const std::optional<Event>& b) {
  if (a.has_value() != b.has_value()) return a ? "streamed error only: " + a->message : "reference error only: " + b->message;
  if (!a) return "";
  if (a->nc_line != b->nc_line || a->block_nr != b->block_nr || a->id != b->id || a->message != b->message)
    return "error differs: " + a->message + " / " + b->message;
  return "";
}

std::string difference(const LiftRange& a, const LiftRange& b) {
  const bool same = a.start == b.start && a.end == b.end && a.end_has_motion == b.end_has_motion &&
                    a.command.pos == b.command.pos && a.z0 == b.z0 && a.peak == b.peak && a.length == b.length &&
                    a.internal_blocks == b.internal_blocks && a.suppressed == b.suppressed &&
                    a.positioning == b.positioning && a.v_plan == b.v_plan && a.v_ahead == b.v_ahead;
  return same ? "" : "lift range " + std::to_string(a.start) + ".." + std::to_string(a.end) + " / " +
                         std::to_string(b.start) + ".." + std::to_string(b.end);
}

struct Run {
  std::vector<Block> blocks;
  std::optional<Event> error;
  std::vector<Event> warnings;
  std::vector<LiftRange> ranges;
};

// As the channel reads a program (ProgramStream), over `text`.
Run streamed(const ProgramText& text, const MachineConfig& machine, const std::vector<double>& start) {
  Run run;
  ProgramStream stream(text, machine, start, [&](LiftRange r) { run.ranges.push_back(std::move(r)); });
  Block block;
  while (stream.blocks().next(block)) run.blocks.push_back(std::move(block));
  run.error = stream.take_error();
  run.warnings = stream.take_warnings();
  return run;
}

// As the channel read it before: decode all, pre-output over all, lift ranges over all.
Run whole(const std::string& text, const MachineConfig& machine, const std::vector<double>& start) {
  Run run;
  DecodedProgram p = reference::whole_decode_program(text, machine, start);
  run.error = p.error;
  run.blocks = reference::whole_m_pre_output(std::move(p.blocks), machine, run.warnings);
  run.ranges = prepare_lift_ranges(run.blocks, machine, start);
  return run;
}

// "" if the streamed run equals the whole-program one.
std::string compare(const std::string& text, const MachineConfig& machine, const std::vector<double>& start) {
  const Run a = streamed(program_text(text), machine, start), b = whole(text, machine, start);
  if (a.blocks.size() != b.blocks.size())
    return std::to_string(a.blocks.size()) + " blocks streamed, " + std::to_string(b.blocks.size()) + " before";
  for (size_t i = 0; i < a.blocks.size(); ++i)
    if (std::string d = difference(a.blocks[i], b.blocks[i]); !d.empty()) return "block " + std::to_string(i) + ": " + d;
  if (std::string d = difference(a.error, b.error); !d.empty()) return d;
  if (a.warnings.size() != b.warnings.size()) return "warnings differ";
  for (size_t i = 0; i < a.warnings.size(); ++i)
    if (a.warnings[i].message != b.warnings[i].message || a.warnings[i].nc_line != b.warnings[i].nc_line)
      return "warning differs: " + a.warnings[i].message;
  if (a.ranges.size() != b.ranges.size()) return "lift range count differs";
  for (size_t i = 0; i < a.ranges.size(); ++i)
    if (std::string d = difference(a.ranges[i], b.ranges[i]); !d.empty()) return d;
  // The decoder alone (decode_program) as well.
  const DecodedProgram p = decode_program(text, machine, start), q = reference::whole_decode_program(text, machine, start);
  if (p.blocks.size() != q.blocks.size()) return "decode_program: block count differs";
  for (size_t i = 0; i < p.blocks.size(); ++i)
    if (std::string d = difference(p.blocks[i], q.blocks[i]); !d.empty()) return "decode_program block " + std::to_string(i) + ": " + d;
  return difference(p.error, q.error);
}

// Random programs of the features whose state or look-back the stream
// carries: $FOR loops (nested), P parameters, M functions with a pre-output
// path, #DEL DIST2GO markers, #TIME, M00, lift ranges, #FLUSH, G91, arcs,
// comments, and now and then a line in error.
class Generator {
 public:
  explicit Generator(uint32_t seed) : rng_(seed) {}
  std::string program(bool lift) {
    std::ostringstream out;
    out << "%gen\nN1 G01 X0 Y0 Z0 F3000\n";
    if (below(2)) out << "V.G.M_FCT[" << 10 + below(3) << "].PRE_OUTP_PATH = " << below(60) << "." << below(10) << "\n";
    const int lines = 5 + below(60);
    int depth = 0, n = 10;
    bool in_range = false;
    for (int i = 0; i < lines; ++i) {
      out << 'N' << (n += 10) << ' ';
      switch (below(lift ? 16 : 13)) {
        case 0: out << "G91 X" << coordinate() << " Y" << coordinate() << "\nG90"; break;
        case 1: out << "P" << 1 + below(3) << " = " << below(20) << " + P" << 1 + below(3); break;
        case 2:
          if (depth < 3) {
            out << "$FOR P" << 5 + depth << " = 1, " << 1 + below(4);
            ++depth;
          } else {
            out << "X" << coordinate();
          }
          break;
        case 3:
          if (depth > 0) {
            out << "$ENDFOR";
            --depth;
          } else {
            out << "Y" << coordinate();
          }
          break;
        case 4: out << "M" << 10 + below(4); break;
        case 5: out << "X" << coordinate() << " M" << 10 + below(4); break;
        case 6: out << "#DEL DIST2GO [END=" << 1 + below(3) << "]"; break;
        case 7: out << "#TIME 0." << below(10); break;
        case 8: out << "G02 X" << 0 << " Y0 I" << 1 + below(5) << " (full circle)"; break;
        case 9: out << (below(8) == 0 ? "X1 Q5 ; an error" : "X[P1 + 1]"); break;
        case 10: out << "M0" << below(2); break;
        case 11: out << "X" << coordinate() << " Y" << coordinate() << " Z" << coordinate(); break;
        case 12: out << "X P" << 1 + below(3) << " Y" << coordinate(); break;
        case 13:
          if (!in_range) {
            out << "Z[LIFT_START POS=" << 5 + below(10) << " POS_LIMIT=" << 20 + below(10) << "]";
            in_range = true;
          } else {
            out << "Z[LIFT_END]";
            in_range = false;
          }
          break;
        case 14: out << (in_range ? "#FLUSH" : "X" + std::to_string(below(50))); break;
        case 15: out << "X" << coordinate() << " Y" << coordinate(); break;
      }
      out << '\n';
    }
    while (depth-- > 0) out << "$ENDFOR\n";
    if (below(4)) out << "M30\n";
    return out.str();
  }

 private:
  int below(int n) { return static_cast<int>(rng_() % static_cast<uint32_t>(n)); }
  std::string coordinate() { return std::to_string(below(100)) + "." + std::to_string(below(1000)); }
  std::mt19937 rng_;
};

}  // namespace

TEST_CASE("issue 17 KRN-1 KRN-2: every scenario's program streamed gives the blocks, error and lift ranges of "
          "the whole-program decoding",
          "[decoder][stream]") {
  int programs = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(std::string(HIL_SOURCE_DIR) + "/scenarios")) {
    if (entry.path().extension() != ".yaml") continue;
    Scenario scenario;
    try {
      scenario = load_scenario_file(entry.path().string());
    } catch (const std::exception&) {
      continue;  // a manifest or a fragment, not a scenario
    }
    INFO(entry.path().string());
    const std::vector<double> start(scenario.machine.axes.size(), 0.0);
    CHECK(compare(scenario.nc_program, scenario.machine, start) == "");
    ++programs;
  }
  CHECK(programs > 50);
}

TEST_CASE("issue 17 KRN-1 P-CHAN-00070 DDTG-5 LIFT-1 LIFT-5: generated programs ($FOR, P parameters, pre-output, "
          "markers, lift ranges, errors) streamed equal the whole-program decoding",
          "[decoder][stream]") {
  const MachineConfig plain = test::xyz_machine(), lifting = test::xyz_lifting_machine(),
                      advanced = test::xyz_lift_machine();
  Generator generator(20261130);
  int errors = 0, ranges = 0;
  for (int i = 0; i < 3000; ++i) {
    const int kind = i % 3;
    const MachineConfig& machine = kind == 0 ? plain : kind == 1 ? lifting : advanced;
    const std::string text = generator.program(kind != 0);
    INFO(text);
    REQUIRE(compare(text, machine, {0, 0, 0}) == "");
    const Run run = whole(text, machine, {0, 0, 0});
    errors += run.error ? 1 : 0;
    ranges += static_cast<int>(run.ranges.size());
  }
  CHECK(errors > 100);  // the generator reaches errors ...
  CHECK(ranges > 300);  // ... and lift ranges
}

TEST_CASE("issue 17: a program streamed from a file equals the same text from a string", "[decoder][stream]") {
  const MachineConfig machine = test::xyz_machine();
  Generator generator(7);
  const std::string path = std::filesystem::temp_directory_path() / "hil_stream_decode_test.nc";
  for (int i = 0; i < 50; ++i) {
    const std::string text = generator.program(false);
    std::ofstream(path) << text;
    const Run from_file = streamed(program_file(path), machine, {0, 0, 0});
    const Run from_string = streamed(program_text(text), machine, {0, 0, 0});
    REQUIRE(from_file.blocks.size() == from_string.blocks.size());
    for (size_t k = 0; k < from_file.blocks.size(); ++k) CHECK(difference(from_file.blocks[k], from_string.blocks[k]) == "");
    CHECK(difference(from_file.error, from_string.error) == "");
  }
  std::remove(path.c_str());
  // A file that cannot be opened has no lines: no block, no error (as an empty text).
  const Run missing = streamed(program_file(path + ".missing"), machine, {0, 0, 0});
  CHECK(missing.blocks.empty());
  CHECK_FALSE(missing.error);
}

TEST_CASE("issue 17 KRN-2: the streamed decoder holds one line and no block of a plain program; a $FOR loop's "
          "body while it runs; an error far ahead surfaces when the stream reaches it, with its line and N",
          "[decoder][stream]") {
  const MachineConfig machine = test::xyz_machine();
  std::string text;
  for (int i = 1; i <= 20000; ++i) text += "N" + std::to_string(i) + " G01 X" + std::to_string(i % 100) + " F6000\n";
  text += "N20001 $FOR P1 = 1, 3\nN20002 X1\nN20003 X2\nN20004 $ENDFOR\n";
  text += "N20005 X1 Q5\nN20006 X9\n";
  ProgramDecoder decoder(std::make_unique<StringLines>(text), machine, {0, 0, 0});
  Block block;
  size_t most_lines = 0, most_blocks = 0, count = 0;
  while (decoder.next(block)) {
    ++count;
    if (block.nc_line <= 20000) {
      most_lines = std::max(most_lines, decoder.lines_held());
      most_blocks = std::max(most_blocks, decoder.blocks_held());
      if (block.nc_line < 20000) CHECK_FALSE(decoder.error());  // not yet met
    }
  }
  CHECK(count == 20000 + 6);
  CHECK(most_lines <= 1);
  CHECK(most_blocks == 0);
  REQUIRE(decoder.error());
  CHECK(decoder.error()->nc_line == 20005);
  CHECK(decoder.error()->block_nr == 20005);
}

TEST_CASE("issue 17 KRN-5 DDTG-5 DPS-3: the channel holds a bounded number of blocks of a long program; what "
          "P-STUP-00033 stores for backward motion bounds its history",
          "[channel][stream]") {
  MachineConfig machine = test::xyz_machine();
  machine.fb_storage_size = 50 * sizeof(Block);  // 50 motion blocks stored for backward motion
  // 20,000 short blocks on a line (0.05 mm at 100 mm/s: 2 per cycle), a marker now and then.
  std::string text = "N1 G01 X0 Y0 Z0 F6000\n";
  for (int i = 1; i <= 20000; ++i) {
    text += "X" + std::to_string(i * 0.05) + "\n";
    if (i % 1000 == 999) text += "#DEL DIST2GO [END=1]\n";
  }
  text += "M30\n";
  Channel channel(machine, text);
  HliControl control;
  control.program_start.enable_w = true;
  size_t most = 0;
  int64_t cycle = 0;
  for (; cycle < 30000 && !channel.finished(); ++cycle) {
    control.program_start.command_w = cycle >= 1;
    channel.step(cycle, control);
    most = std::max(most, channel.blocks_held());
  }
  CHECK(channel.finished());
  CHECK(channel.hli().channel_state == ChannelState::program_end);
  // The look-ahead (120 blocks), the stored contour (50 motion blocks),
  // what the stages hold (10 motion blocks for pre-output, one line ahead).
  CHECK(most <= 120 + 50 + 60);
  CHECK(most >= 50);
}

TEST_CASE("issue 17 DDTG-5 DDTG-6: the short-cut target search reads ahead at most short_cut_search_blocks blocks",
          "[ddtg][stream]") {
  std::vector<Block> blocks(short_cut_search_blocks + 10);
  for (size_t i = 0; i < blocks.size(); ++i) {
    blocks[i].has_motion = true;
    blocks[i].motion.start = {double(i), 0, 0};
    blocks[i].motion.end = {double(i + 1), 0, 0};
  }
  blocks.back().ddtg_end_marker = 1;  // beyond the search
  ShortCutTarget far = short_cut_target(blocks, 0, 1);
  CHECK_FALSE(far.target);
  CHECK(far.search_limit);
  blocks[short_cut_search_blocks - 5].ddtg_end_marker = 1;  // within it
  ShortCutTarget near = short_cut_target(blocks, 0, 1);
  REQUIRE(near.target);
  CHECK(*near.target == short_cut_search_blocks - 6);
  CHECK_FALSE(near.search_limit);
}

TEST_CASE("issue 17 DPS-3: block search on a long program passes it once and keeps only what it needs", "[channel][stream]") {
  MachineConfig machine = test::xyz_machine();
  std::string text = "N1 G01 X0 Y0 Z0 F6000\n";
  for (int i = 2; i <= 20000; ++i) text += "N" + std::to_string(i) + " X" + std::to_string((i % 2) * 10) + "\n";
  text += "M30\n";
  Channel channel(machine, text);
  HliControl control;
  control.program_start.enable_w = true;
  control.block_search.enable_w = true;
  control.block_search.command_w.type = 4;
  control.block_search.command_w.block_nr = 19000;
  control.block_search.command_w.distance = (18997 * 10.0 + 4) * hli_units_per_mm;  // 4 mm into N19000 (N3 .. N18999: 10 mm each)
  channel.step(0, control);
  control.program_start.command_w = true;
  channel.step(1, control);
  CHECK(channel.hli().block_search.state_r.state == block_search_state::repositioning);
  CHECK(channel.hli().block_search.state_r.continuation_block_nr == 19000);
  CHECK(channel.blocks_held() < 300);
}

TEST_CASE("issue 17 KRN-1: the endless-loop limit counts lines read again by $FOR loops, not a program's length",
          "[decoder][stream]") {
  const MachineConfig machine = test::xyz_machine();
  std::string text = "G01 F6000\n";
  for (int i = 1; i <= 50; ++i) text += "X" + std::to_string(i) + "\n";
  const DecodedProgram long_program = decode_program(text, machine, {0, 0, 0}, 10);
  CHECK_FALSE(long_program.error);
  CHECK(long_program.blocks.size() == 50);
  const DecodedProgram loop =
      decode_program("G01 F6000\n$FOR P1 = 1, 100\nX1\nX2\n$ENDFOR\n", machine, {0, 0, 0}, 10);
  REQUIRE(loop.error);
  CHECK_THAT(loop.error->message, Catch::StartsWith("more than 10 lines read again by $FOR loops"));
}
