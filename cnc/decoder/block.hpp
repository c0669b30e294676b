#pragma once
// What the decoder hands on: one entry per NC program line that commands
// something (KRN-1). Positions are absolute, in machine axis order, mm.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "axis_values.hpp"
#include "slope.hpp"

namespace hil::cnc {

enum class MotionType { rapid, linear, arc_cw, arc_ccw };  // G00 G01 G02 G03

struct Motion {
  MotionType type = MotionType::linear;
  AxisValues start;     // mm, per machine axis
  AxisValues end;       // mm, per machine axis
  // G02/G03: the machine axes of the plane (G17 X Y, G18 Z X, G19 Y Z; the
  // first to the second is counter-clockwise, G03), -1: X and Y. Axes
  // outside it move linearly along the arc (a helix).
  std::array<int, 2> plane{-1, -1};
  std::array<double, 2> center{};  // mm, the absolute arc centre on the plane's axes
  double feed = 0;      // mm/s (programmed F is mm/min), the F in force; G00 moves at rapid
  // The lift function's caps on the path in a lift range (LIFT-2, LIFT-3):
  // velocity so that the lift axis makes its target in time, and (path-based)
  // acceleration and jerk so that the coupled lift axis stays within its
  // overload range. Infinite: none.
  Limits path_caps = Limits::none();
  // The block lies in a lift range (set with path_caps): a corner there
  // keeps the curve whose speed the lift's landing allows for (ContourBuilder).
  bool in_lift_range = false;
};

// #DISTANCE PROG START ON / OFF (modal) / CLEAR (DPS-2).
enum class DistanceProgStart { on, off, clear };

// What a delete distance to go short cut may not pass (DDTG-8): commands
// that must not be skipped (#CS ON/OFF: error 51016), and commands that need
// channel initialisation (#CHANNEL INIT: the short cut ends before them,
// warning 51036).
enum class ShortCutRestriction : uint8_t { none, not_skippable, channel_initialisation };

// How the path passes from a motion block into the next (KRN-6).
enum class BlockTransition : uint8_t {
  standard,    // G260/G359 (initial): corners stop, tangent transitions pass at the corner rule's velocity
  contour,     // G261 (modal) or G61 (this block): the corner is replaced by a contouring curve
  exact_stop,  // G360 (modal) or G60 (this block): v = 0 at the block end, also on a straight line
};

// #CONTOUR MODE [DEV PATH_DEV=..] / [DIST DIST=..] (KRN-6).
struct ContourMode {
  enum class Type : uint8_t { dev, dist };
  Type type = Type::dev;
  double path_dev = 0.01;  // mm, DEV: largest distance between the programmed corner and the curve
  double dist = 0;         // mm, DIST: distance of the curve's ends from the corner
};

// #HSC ON [BSPLINE ..] (KRN-9, programming manual "Trim a contour"): runs
// of short G01 blocks are smoothed into one curvature-continuous spline
// (cnc/path/hsc_spline.hpp, docs/HSC.md). Defaults as the manual's.
struct HscMode {
  bool on = false;
  double path_dev = 0.2;        // mm, main axes; 0: not monitored
  double track_dev = 5;         // degrees (mm for a linear axis) of the other axes; 0: not monitored
  bool merge = false;           // MERGE=1: a spline span takes several blocks
  bool auto_off_path = false;   // AUTO_OFF_PATH=1: a span beyond PATH_DEV keeps its blocks' corners
  bool auto_off_track = false;  // AUTO_OFF_TRACK=1: likewise for TRACK_DEV
  bool auto_off_g00 = false;    // AUTO_OFF_G00=1: a G00 block switches HSC off
  bool auto_off_g60 = false;    // AUTO_OFF_G60=1: G60 / G360 switch HSC off
  double max_path_length = 0;   // mm: a longer block ends the spline; 0: any length
  double max_angle = 0;         // degrees: a sharper bend stays a corner; 0: the rig's hsc_corner_angle_deg
};

// A technology function of a line for the PLC (MVS_SVS): M<nr>, H<nr>,
// T<nr>, S<value> (rpm; with M03 / M04 or while the spindle turns) or
// D<nr> (the tool offset, shown on the HLI without a handshake), KRN-8;
// and how far along the path before its line an M function is to be
// output (path-related pre-output, P-CHAN-00070), mm.
struct MFunction {
  int nr = 0;
  double pre_output_mm = 0;
  char address = 'M';
  double value = 0;  // S: rpm
  bool operator==(const MFunction& other) const {
    return nr == other.nr && pre_output_mm == other.pre_output_mm && address == other.address && value == other.value;
  }
};

// A stop mark (ISC-1, ISC-8): where and how, as the insert command unit's
// command_w has it.
struct InsertCommand {
  double dist_or_pos = 0;  // 0.1 um
  int rel_abs_mode = 0;    // 0 relative iterative, 1 absolute, 2 relative once
  int axis_nr = 0;         // 0 DISTANCE mode, > 0 POSITION mode (1 = the first machine axis)
  int m_function_nr = 0;   // 0 M00, 1 M01, > 1 M<n> (MVS_SVS)
  int32_t add_nr = 0;
};
// #INSERT CMD [ON|OFF] [..] (ISC-8).
struct InsertCmdLine {
  bool off = false;  // OFF: the mark is cleared, insertion disabled until ON
  std::optional<InsertCommand> command;
};

// <axis>[LIFT_START ..] or the single-block <axis>[LIFT ..] (LIFT-1): a lift
// range begins with this block (its motion, if it has one, lies in it).
// Positions absolute, G91 resolved against where the lift axis stands.
struct LiftStart {
  int axis = 0;          // machine axis index of the lift axis
  bool down = false;     // DOWN: lowering instead of lifting (Advanced Lifting only)
  double pos = 0;        // mm, where the lift axis lands at the range's end (POS; default: where it stands)
  double pos_limit = 0;  // mm, the highest lift (DOWN: the deepest lowering), POS_LIMIT
};

struct Block {
  int64_t nc_line = 0;   // 1-based line of the NC program
  // Lines the decoder has read up to this one, repeated lines ($FOR)
  // included: the HLI's block_count_r.
  int64_t block_count = 0;
  int64_t block_nr = 0;  // N number, 0 if the line has none
  bool has_motion = false;
  // The rest of the motion block before it, split off where a pre-output M
  // function goes out (apply_m_pre_output): the same programmed block.
  bool continues_block = false;
  ShortCutRestriction short_cut_restriction = ShortCutRestriction::none;
  Motion motion;
  SlopeType slope = SlopeType::trapez;  // #SLOPE[TYPE=..] in force for the motion
  std::optional<DistanceProgStart> distance_prog_start;
  // #DEL DIST2GO [END=..]: a short-cut target, valid while the PLC's
  // activation mask shares a bit with it (DDTG-5).
  std::optional<uint32_t> ddtg_end_marker;
  bool program_end = false;  // M30
  // M functions of the line, output to the PLC before the line's motion and
  // acknowledged by it before the motion starts (MVS_SVS), in order.
  std::vector<MFunction> m_functions;
  double dwell_s = 0;  // #TIME: the path waits this long, s
  // How the path leaves this motion block (KRN-6), with the contour mode in force.
  BlockTransition transition = BlockTransition::standard;
  ContourMode contour;
  HscMode hsc;  // in force for this motion block (KRN-9)
  std::optional<int> programmed_stop;  // M00 (0) or M01 (1), ISC-5
  std::optional<InsertCmdLine> insert_cmd;
  // The lift function (LIFT-1, LIFT-5): a range begins with this block, and
  // it ends after this block's motion (Z[LIFT_END], the single-block
  // Z[LIFT ..], #FLUSH / #FLUSH WAIT which also begins the next one, M30).
  // A range without an end ends with the program's last block.
  std::optional<LiftStart> lift_start;
  bool lift_end = false;
  // Set by the lift's preparation (lift_ranges): a range without path
  // motion; the path stands here while the lift axis positions (LIFT-2).
  bool lift_positioning = false;
  // A command a distance search cannot simulate (DPS-3): "G74", "G100" or
  // "#FLUSH WAIT"; empty otherwise. Nothing for the interpolator to do.
  std::string not_searchable;

  // The path stands still where this block is reached: for the PLC's
  // acknowledgement, a dwell, or a channel initialisation.
  bool stops_path() const {
    return !m_functions.empty() || dwell_s > 0 || programmed_stop || insert_cmd ||
           short_cut_restriction == ShortCutRestriction::channel_initialisation || lift_positioning;
  }
  // Anything besides moving that keeps the block: a command for the
  // interpolator, or a mark for block search (not_searchable).
  bool has_command() const {
    return distance_prog_start || ddtg_end_marker || stops_path() || program_end ||
           short_cut_restriction != ShortCutRestriction::none || !not_searchable.empty();
  }
};

}  // namespace hil::cnc
