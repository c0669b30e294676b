#include "program_generator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <stdexcept>

#include "fuzz_rng.hpp"

namespace hil::fuzz {

const char* to_string(ProgramKind kind) {
  switch (kind) {
    case ProgramKind::mixed: return "mixed";
    case ProgramKind::lines: return "lines";
    case ProgramKind::arcs: return "arcs";
    case ProgramKind::steps: return "steps";
    case ProgramKind::commands: return "commands";
    case ProgramKind::contour: return "contour";
    case ProgramKind::lift: return "lift";
    case ProgramKind::hsc: return "hsc";
  }
  return "?";
}

std::optional<ProgramKind> parse_program_kind(const std::string& name) {
  for (ProgramKind kind : named_program_kinds)
    if (name == to_string(kind)) return kind;
  return std::nullopt;
}

MachineConfig xyz_fuzz_machine(int32_t override_max_percent, LiftMethod lift) {
  MachineConfig m;
  m.lift_method = lift;
  m.name = "xyz_mill (fuzz)";
  m.cycle_time_us = 1000;
  m.override_max_percent = override_max_percent;
  m.fb_storage_size = 1000000;
  auto axis = [](const char* name, double v, double a, double j, double kv, double lag) {
    AxisConfig c;
    c.name = name;
    c.v_max = c.v_rapid = v;
    c.a_max = a;
    c.j_max = j;
    c.kv = kv;
    c.velocity_lag_s = lag;
    c.slep_max = 0.5;
    return c;
  };
  m.axes = {axis("X", 250, 2000, 40000, 40, 0.002), axis("Y", 250, 2000, 40000, 40, 0.002),
            axis("Z", 150, 1500, 30000, 35, 0.0025)};
  return m;
}

namespace {

using Vec = std::array<double, 3>;  // X Y Z

double norm(const Vec& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

// Up to 9 decimals (1 pm), trailing zeros trimmed: what the program says.
std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9f", v);
  std::string s(buf);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}
// What the decoder reads from it.
double read_back(const std::string& text) { return std::strtod(text.c_str(), nullptr); }

// Collinear directions whose steps stay collinear to round-off: small
// integer vectors (a random float direction is rarely collinear within the
// corner rule's 1e-12, so its steps are corners).
constexpr int step_directions[][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {3, 4, 0}, {1, -2, 0},
                                      {1, 1, 1}, {2, -1, 2}, {-4, 3, 0}, {5, 0, -1}};

enum Item {
  long_line, short_line, tiny_line, rapid, steps, arc_random, tangent_chain, full_circle, helix, tiny_arc,
  g91_section, feed_change, m_alone, m_with_motion, dwell, marker, dps_command, slope,
  contour_mode, chord_polyline, near_collinear, lift_range, hsc_switch, item_count
};

// Weights of the items per program kind (columns in Item order).
constexpr double weights[][item_count] = {
    //        long short tiny rapid steps arc  chain full helix tinyarc g91 feed m   m+mv dwell mark dps slope
    //        contour-mode chord-polyline near-collinear lift-range hsc-switch
    /*mixed*/ {2, 2, 1, 1, 1.5, 1.5, 1.5, 0.5, 0.5, 0.5, 1, 1, 0.7, 0.7, 0.5, 0.7, 0.6, 0.5, 0, 0, 0, 0, 0},
    /*lines*/ {3, 3, 1, 1.5, 1, 0, 0, 0, 0, 0, 1, 1.5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    /*arcs*/ {0, 1, 0, 0, 0, 3, 3, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    /*steps*/ {0, 1, 2, 0, 6, 0, 0, 0, 0, 0, 0.5, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    /*commands*/ {1, 2, 0, 0, 0.5, 0.5, 0, 0, 0, 0, 0.3, 0.5, 2, 2, 1.5, 2, 1.5, 0, 0, 0, 0, 0, 0},
    /*contour*/ {1, 2, 1, 0.5, 1.5, 1, 1.5, 0.3, 0.3, 0.3, 0.5, 1, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 2.5, 4, 2, 0, 0},
    /*lift*/ {1.5, 1.5, 0.5, 1, 0.5, 1, 0.5, 0.2, 0.3, 0.3, 0.3, 1, 0.5, 0.5, 0.3, 0, 0.3, 0.3, 0.7, 0.3, 0, 4, 0},
    /*hsc*/ {1, 1.5, 0.5, 0.7, 0.5, 1, 0.7, 0.2, 0.2, 0.2, 0.3, 1, 0.3, 0.3, 0.3, 0.3, 0.3, 0.2, 0.3, 6, 2, 0, 1.5},
};

// What may stand inside a lift range: no motion of the lift axis Z (LIFT-6).
// No #DEL DIST2GO markers in lift programs: a short cut past a lift
// command is error 51016 (DDTG-8), tested on its own.
constexpr Item in_lift_items[] = {long_line, short_line, tiny_line, rapid,         arc_random, tangent_chain, full_circle,
                                  tiny_arc,  feed_change, m_alone,  m_with_motion, dwell,      dps_command,   slope};

class Generator {
 public:
  Generator(uint64_t seed, const ProgramOptions& options, const MachineConfig& machine)
      : rng_(seed), options_(options), machine_(machine) {
    ix_ = machine.axis_index("X");
    iy_ = machine.axis_index("Y");
    iz_ = machine.axis_index("Z");
    if (ix_ < 0 || iy_ < 0 || iz_ < 0) throw std::invalid_argument("the fuzz programs need axes X, Y and Z");
    out_.end_position.assign(machine.axes.size(), 0.0);
    seed_ = seed;
  }

  GeneratedProgram run() {
    out_.lines.push_back("%fuzz" + std::to_string(seed_));
    set_feed(random_feed());
    emit("G90 G01 F" + feed_word_);
    if (options_.kind == ProgramKind::contour) {
      contour_switch(true);
      emit(rng_.chance(0.8) ? "G261" : "#CONTOUR MODE ON");
    }
    if (options_.kind == ProgramKind::hsc) {
      decimals_ = rng_.chance(0.5) ? 4 : 3;
      hsc_command(true);
    }
    const int items = static_cast<int>(rng_.integer(options_.min_items, options_.max_items));
    for (int i = 0; i < items; ++i) item(pick_item(false));
    if (!absolute_) emit("G90");
    if (in_lift_) pos_[2] = lift_pos_;  // M30 ends the range (LIFT-5)
    emit("M30");
    for (const std::string& line : out_.lines) out_.text += line + "\n";
    out_.end_position[ix_] = pos_[0];
    out_.end_position[iy_] = pos_[1];
    out_.end_position[iz_] = pos_[2];
    out_.dist_prog_start_end_mm = dps_;
    for (const std::string& line : out_.lines) {
      out_.contoured = out_.contoured || switches_contouring_on(line);
      out_.hsc = out_.hsc || switches_hsc_on(line);
    }
    return out_;
  }

 private:
  Item pick_item(bool in_g91) {
    if (in_lift_) return in_lift_items[rng_.integer(0, std::size(in_lift_items) - 1)];
    const double(&w)[item_count] = weights[static_cast<int>(options_.kind)];
    for (;;) {
      const Item it = static_cast<Item>(rng_.pick(w));
      if (in_g91 && (it == g91_section || it == lift_range)) continue;
      return it;
    }
  }

  // LIFT-1: a lift range around a few items (#FLUSH now and then, left
  // open to M30 now and then), or a single-block lift on an XY line. POS
  // left out, between, or beyond POS_LIMIT (LIFT-5); G91; DOWN only where
  // the machine lifts time-based.
  void lift() {
    const bool down = machine_.lift_method == LiftMethod::time_based && rng_.chance(0.2);
    const double z = pos_[2], sign = down ? -1 : 1;
    const bool relative = rng_.chance(0.3);
    std::string words = std::string(down ? " DOWN" : "") + (relative ? " G91" : rng_.chance(0.2) ? " G90" : "");
    auto value = [&](double at, const char* key, double& got) {
      const std::string text = num(relative ? at - z : at);
      got = relative ? z + read_back(text) : read_back(text);
      words += std::string(" ") + key + "=" + text;
    };
    out_.lifts = true;
    double limit = 0, pos = z;
    const double limit_wanted = z + sign * rng_.log_uniform(0.2, 60);
    const size_t pos_kind = rng_.pick({1.0, 3.0, 0.5});  // none, near where it stands, beyond the limit
    if (pos_kind == 1) value(z + rng_.uniform(-10, 10), "POS", pos);
    if (pos_kind == 2) value(limit_wanted + sign * rng_.uniform(0.1, 10), "POS", pos);
    value(limit_wanted, "POS_LIMIT", limit);
    if (rng_.chance(0.2)) {
      extra_ = " Z[LIFT" + words + "]";
      in_lift_ = true;
      const bool moved_xy = line_by(direction(false), rng_.log_uniform(0.5, 50), 1);
      in_lift_ = false;
      extra_.clear();
      if (moved_xy) pos_[2] = pos;
      return;
    }
    emit("Z[LIFT_START" + words + "]");
    in_lift_ = true;
    lift_pos_ = pos;
    const int n = static_cast<int>(rng_.integer(0, 8));
    for (int i = 0; i < n; ++i) {
      if (rng_.chance(0.08)) {  // LIFT-5: LIFT_END and LIFT_START here
        emit(rng_.chance(0.5) ? "#FLUSH" : "#FLUSH WAIT");
        pos_[2] = limit;
        continue;
      }
      item(pick_item(false));
    }
    if (rng_.chance(0.1)) return;  // open to M30 (LIFT-5): the items after it stay in the range
    emit("Z[LIFT_END]");
    in_lift_ = false;
    pos_[2] = pos;
  }

  void item(Item it) {
    switch (it) {
      case long_line: {
        // Long, but no more than ~0.6 s at the feed in force.
        const double l = std::min(rng_.log_uniform(5, 300), std::max(5.0, feed_ * 0.6));
        line_by(direction(rng_.chance(0.2)), l, 1);
        break;
      }
      case short_line: line_by(direction(rng_.chance(0.2)), rng_.log_uniform(0.01, 5), 1); break;
      case tiny_line: line_by(direction(rng_.chance(0.3)), rng_.log_uniform(0.001, 0.01), 1); break;
      case rapid: line_by(direction(rng_.chance(0.4)), rng_.log_uniform(0.5, 150), 0); break;
      case steps: collinear_steps(); break;
      case arc_random: random_arc(rng_.log_uniform(0.05, 60), 0); break;
      case tangent_chain: chain(); break;
      case full_circle: full(); break;
      case helix: random_arc(rng_.log_uniform(0.5, 30), rng_.uniform(-5, 5)); break;
      case tiny_arc: random_arc(rng_.log_uniform(0.001, 0.01), 0); break;
      case g91_section: relative_section(); break;
      case feed_change:
        set_feed(random_feed());
        if (rng_.chance(0.5)) emit("F" + feed_word_);
        else feed_on_next_ = true;
        break;
      case m_alone: emit(m_words()); break;
      case m_with_motion:
        extra_ = " " + m_words();
        if (!line_by(direction(false), rng_.log_uniform(0.01, 20), 1)) emit(extra_.substr(1));
        extra_.clear();
        break;
      case dwell: {
        const double t = std::round(rng_.log_uniform(0.001, 0.3) * 1000) / 1000;
        out_.dwell_s += t;
        emit("#TIME " + num(t));
        break;
      }
      case marker: {
        const int form = static_cast<int>(rng_.integer(0, 3));
        const int end = static_cast<int>(rng_.integer(1, 15));
        char hex[8];
        std::snprintf(hex, sizeof hex, "%02X", end);
        emit(form == 0 ? std::string("#DEL DIST2GO")
             : form == 1 ? "#DEL DIST2GO [END=" + std::to_string(end) + "]"
             : form == 2 ? std::string("#DEL DIST2GO [END='16#") + hex + "']"
                         : std::string("#DEL DIST2GO []"));
        break;
      }
      case dps_command: {
        const size_t which = rng_.pick({1.0, 1.0, 0.7});
        if (which == 0) {
          emit("#DISTANCE PROG START ON");
          counting_ = true;
        } else if (which == 1) {
          emit("#DISTANCE PROG START OFF");
          counting_ = false;
          out_.has_dps_off = true;
        } else {
          emit("#DISTANCE PROG START CLEAR");
          dps_ = 0;
          out_.clear_lines.push_back(static_cast<int64_t>(out_.lines.size()));
        }
        break;
      }
      case slope: emit(rng_.chance(0.5) ? "#SLOPE[TYPE=SIN2]" : "#SLOPE [TYPE=TRAPEZ]"); break;
      case contour_mode: contour_switch(false); break;
      case chord_polyline: polyline(); break;
      case near_collinear: nearly_straight(); break;
      case lift_range: lift(); break;
      case hsc_switch: hsc_command(false); break;
      case item_count: break;
    }
  }

  std::string m_words() {
    std::string words;
    const int count = rng_.chance(0.2) ? 2 : 1;
    for (int i = 0; i < count; ++i) {
      const int m = static_cast<int>(rng_.integer(10, 20));
      out_.m_functions.push_back(m);
      words += (i ? " M" : "M") + std::to_string(m);
    }
    return words;
  }

  double random_feed() {
    // mm/min; mostly 600 .. 15000 (10 .. 250 mm/s), now and then slow or
    // above the axes' limits.
    const size_t which = rng_.pick({0.1, 0.8, 0.1});
    const double f = which == 0 ? rng_.uniform(60, 600) : which == 1 ? rng_.log_uniform(600, 15000)
                                                                     : rng_.uniform(15000, 30000);
    return std::round(f);
  }
  void set_feed(double f_mm_min) {
    feed_word_ = std::to_string(static_cast<int64_t>(f_mm_min));
    feed_ = read_back(feed_word_) / 60.0;
  }

  // A unit direction: mostly in XY, now and then with Z or along one axis;
  // towards the origin when the position wanders far.
  Vec direction(bool with_z) {
    with_z = with_z && !in_lift_;
    Vec d{};
    if (rng_.chance(0.25)) {
      d[rng_.integer(0, with_z ? 2 : 1)] = rng_.chance(0.5) ? 1 : -1;
    } else {
      const double angle = rng_.uniform(0, 2 * M_PI);
      d = {std::cos(angle), std::sin(angle), with_z ? rng_.uniform(-0.5, 0.5) : 0.0};
    }
    if (pos_[0] * d[0] + pos_[1] * d[1] > 0 && std::hypot(pos_[0], pos_[1]) > 250) {
      d[0] = -d[0];
      d[1] = -d[1];
    }
    if (pos_[2] * d[2] > 0 && std::abs(pos_[2]) > 50) d[2] = -d[2];
    const double n = norm(d);
    for (double& c : d) c /= n;
    return d;
  }

  void emit(const std::string& code) {
    const int64_t line = static_cast<int64_t>(out_.lines.size()) + 1;
    out_.lines.push_back("N" + std::to_string(line * 10) + " " + code);
  }

  // The axis words of a move to `want` (G90 absolute, G91 relative) and the
  // position the decoder will compute from them.
  // Axes in `left_out` (bit k: axis k) are not written.
  std::string axis_words(const Vec& want, Vec& got, int left_out = 0) {
    static const char letters[] = {'X', 'Y', 'Z'};
    std::string words;
    got = pos_;
    for (int k = 0; k < 3; ++k) {
      if ((left_out >> k) & 1) continue;
      if (k == 2 && in_lift_) continue;  // the lift axis is not programmed in a range (LIFT-6)
      const bool changed = want[k] != pos_[k];
      if (!changed && !rng_.chance(0.1)) continue;  // now and then an axis that does not move
      const std::string text = num(absolute_ ? want[k] : want[k] - pos_[k]);
      const double value = read_back(text);
      got[k] = absolute_ ? value : pos_[k] + value;
      words += std::string(" ") + letters[k] + text;
    }
    return words;
  }

  std::string feed_words() {
    if (!feed_on_next_ && !rng_.chance(0.1)) return "";
    feed_on_next_ = false;
    return " F" + feed_word_;
  }

  // G00 (g = 0) or G01 (g = 1) by `length` along `d`; false if rounding left no motion.
  bool line_by(const Vec& d, double length, int g) {
    Vec want;
    for (int k = 0; k < 3; ++k) want[k] = pos_[k] + d[k] * length;
    return line_to(want, g);
  }
  bool line_to(const Vec& want, int g) {
    Vec got;
    const std::string words = axis_words(want, got);
    Vec step{got[0] - pos_[0], got[1] - pos_[1], got[2] - pos_[2]};
    const double length = norm(step);
    if (length == 0) return false;
    emit(std::string(g == 0 ? "G00" : "G01") + words + (g == 0 ? "" : feed_words()) + extra_ + transition_next_);
    transition_next_.clear();
    moved(got, length);
    return true;
  }

  void moved(const Vec& got, double length) {
    pos_ = got;
    ++out_.motion_blocks;
    out_.path_length_mm += length;
    if (counting_) dps_ += length;
  }

  // G02/G03 in the plane in force (plane_, KRN-8) with the centre at (i, j)
  // on its first and second axis from the start, to `end_angle` (radians
  // about the centre, from the first axis to the second); none: a full
  // circle. `dz`: the helix's travel on the plane's normal.
  // `quadrant_end`: the end lies exactly on an axis through the centre
  // (tangent chains), quadrant 0..3 = +first, +second, -first, -second.
  // Now and then by radius R instead of the centre (not a full circle).
  bool arc(bool ccw, double i, double j, std::optional<double> end_angle, double dz, int quadrant_end = -1) {
    const int a = plane_.first, b = plane_.second, n = plane_.normal;
    const std::string ti = num(i), tj = num(j);
    double ca = pos_[a] + read_back(ti), cb = pos_[b] + read_back(tj);
    const double r = std::hypot(pos_[a] - ca, pos_[b] - cb);
    if (r < 1e-4) return false;
    const double a0 = std::atan2(pos_[b] - cb, pos_[a] - ca);
    Vec want = pos_;
    want[n] += dz;
    double sweep = 2 * M_PI, a1 = a0;
    if (end_angle || quadrant_end >= 0) {
      if (quadrant_end >= 0) {
        const double off[4][2] = {{r, 0}, {0, r}, {-r, 0}, {0, -r}};
        want[a] = ca + off[quadrant_end][0];
        want[b] = cb + off[quadrant_end][1];
        a1 = quadrant_end * M_PI / 2;
      } else {
        a1 = *end_angle;
        want[a] = ca + r * std::cos(a1);
        want[b] = cb + r * std::sin(a1);
      }
      sweep = std::fmod(ccw ? a1 - a0 : a0 - a1, 2 * M_PI);
      if (sweep < 0) sweep += 2 * M_PI;
      // A sweep next to 0 or 2 pi could read as a full circle or a sliver
      // after rounding: not generated (the intended length must be right).
      if (sweep < 0.02 || sweep > 2 * M_PI - 0.02) return false;
    }
    const bool full = !end_angle && quadrant_end < 0;
    Vec got;
    std::string words = full ? axis_words(want, got, (1 << a) | (1 << b)) : axis_words(want, got);
    if (full) {  // the plane's axes stay
      got[a] = pos_[a];
      got[b] = pos_[b];
    }
    std::string centre = std::string(" ") + plane_.centre[0] + ti + " " + plane_.centre[1] + tj;
    // By radius: the decoder's centre lies on the chord's bisector, at R
    // as written; the sweep is what that circle gives (the oracle's length).
    if (!full && sweep > 0.1 && sweep < 2 * M_PI - 0.1 && std::abs(sweep - M_PI) > 0.05 && rng_.chance(0.3)) {
      const std::string tr = num(sweep > M_PI ? -r : r);
      const double rr = std::abs(read_back(tr));
      const double ha = (got[a] - pos_[a]) / 2, hb = (got[b] - pos_[b]) / 2, half = std::hypot(ha, hb);
      if (half > 1e-6 && rr >= half) {
        const double height = std::sqrt(rr * rr - half * half), side = (ccw ? 1 : -1) * (sweep > M_PI ? -1 : 1);
        ca = pos_[a] + ha - side * height * hb / half;
        cb = pos_[b] + hb + side * height * ha / half;
        const double s0 = std::atan2(pos_[b] - cb, pos_[a] - ca), s1 = std::atan2(got[b] - cb, got[a] - ca);
        double by_radius = std::fmod(ccw ? s1 - s0 : s0 - s1, 2 * M_PI);
        if (by_radius < 0) by_radius += 2 * M_PI;
        if (by_radius > 0.02 && by_radius < 2 * M_PI - 0.02 && std::abs(by_radius - sweep) < 0.1) {
          centre = " R" + tr;
          sweep = by_radius;
        }
      }
    }
    const double r_end = std::hypot(got[a] - ca, got[b] - cb);
    // The decoder allows P-CHAN-00171's 5 um; the kernel blends the radius
    // along the arc. Kept at round-off, so that the path is the intended circle.
    if (std::abs(r - r_end) > 1e-9 * (1 + r) && centre[1] != 'R') return false;
    if (in_lift_) got[2] = pos_[2];
    const double z = got[n] - pos_[n];
    const double planar = (centre[1] == 'R' ? std::hypot(pos_[a] - ca, pos_[b] - cb) : r) * sweep,
                 length = std::hypot(planar, z);
    emit(std::string(ccw ? "G03" : "G02") + words + centre + feed_words() + extra_ + transition_next_);
    transition_next_.clear();
    moved(got, length);
    return true;
  }

  // The plane of the next arcs: G17 mostly; G18 / G19 (Z in the plane) not
  // in a lift range, where Z is the lift axis (LIFT-6).
  void choose_plane() {
    const int plane = in_lift_ || !rng_.chance(0.35) ? 17 : rng_.chance(0.5) ? 18 : 19;
    if (plane == plane_.g) return;
    plane_ = plane == 17 ? g17 : plane == 18 ? g18 : g19;
    emit("G" + std::to_string(plane));
  }

  void random_arc(double r, double dz) {
    choose_plane();
    const double a0 = rng_.uniform(0, 2 * M_PI), sweep = rng_.uniform(0.05, 2 * M_PI - 0.05);
    const bool ccw = rng_.chance(0.5);
    // The centre seen from the start.
    const double i = -r * std::cos(a0), j = -r * std::sin(a0);
    arc(ccw, i, j, a0 + (ccw ? sweep : -sweep), dz);
  }

  void full() {
    choose_plane();
    const double r = rng_.log_uniform(0.01, 20), a0 = rng_.uniform(0, 2 * M_PI);
    arc(rng_.chance(0.5), -r * std::cos(a0), -r * std::sin(a0), std::nullopt, rng_.chance(0.3) ? rng_.uniform(-3, 3) : 0);
  }

  // Lines along X or Y and quarter/half arcs tangent to them and to each
  // other: the transitions are tangent, the curvature steps (line <-> arc,
  // S-bends, radius changes); the corner rule's curvature part.
  void chain() {
    if (plane_.g != 17) {
      plane_ = g17;
      emit("G17");
    }
    // Start along an axis: a short line sets the direction exactly.
    int q = static_cast<int>(rng_.integer(0, 3));  // direction +X, +Y, -X, -Y
    const double unit[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    auto straight = [&](double l) {
      Vec want = pos_;
      want[0] += unit[q][0] * l;
      want[1] += unit[q][1] * l;
      line_to(want, 1);
    };
    straight(std::round(rng_.log_uniform(0.1, 20) * 1000) / 1000);
    const int pieces = static_cast<int>(rng_.integer(1, 6));
    for (int p = 0; p < pieces; ++p) {
      if (rng_.chance(0.3)) {
        straight(std::round(rng_.log_uniform(0.01, 20) * 1000) / 1000);
        continue;
      }
      const bool ccw = rng_.chance(0.5);
      const double r = std::round(rng_.log_uniform(0.05, 40) * 1000) / 1000;
      // The centre lies to the left (G03) or right (G02) of the direction q.
      const int to_centre = ccw ? (q + 1) % 4 : (q + 3) % 4;
      const int quarters = static_cast<int>(rng_.integer(1, 3));
      // The start lies at the quadrant opposite to_centre, seen from the centre.
      const int start_quadrant = (to_centre + 2) % 4;
      const int end_quadrant = ((ccw ? start_quadrant + quarters : start_quadrant - quarters) % 4 + 4) % 4;
      if (arc(ccw, unit[to_centre][0] * r, unit[to_centre][1] * r, std::nullopt, 0, end_quadrant))
        q = ccw ? (end_quadrant + 1) % 4 : (end_quadrant + 3) % 4;  // the tangent there
    }
  }

  // Short collinear steps at a high feed, then a reversal (or a sharp
  // corner): the path must brake within the steps for the turn.
  void collinear_steps() {
    Vec d{};
    bool exact = rng_.chance(0.85);
    if (exact) {
      const int* v = step_directions[rng_.integer(0, std::size(step_directions) - 1)];
      const double s = rng_.chance(0.5) ? 1 : -1;
      d = {s * v[0], s * v[1], s * v[2]};
    } else {
      d = direction(rng_.chance(0.2));
    }
    const size_t scale = rng_.pick({1.0, 2.0, 2.0, 1.0});
    const double h = scale == 0 ? 0.001 : scale == 1 ? 0.01 * rng_.integer(1, 50)
                   : scale == 2 ? 0.1 * rng_.integer(1, 20) : rng_.integer(1, 5);
    const int n = static_cast<int>(rng_.integer(2, 12));
    const bool even = rng_.chance(0.6);
    if (rng_.chance(0.7)) {
      set_feed(std::round(rng_.uniform(3000, 15000)));
      feed_on_next_ = true;
    }
    const Vec start = pos_;
    int64_t m = 0;
    for (int i = 0; i < n; ++i) {
      m += even ? 1 : rng_.integer(1, 4);
      Vec want;
      for (int k = 0; k < 3; ++k) want[k] = exact ? start[k] + d[k] * h * m : pos_[k] + d[k] * h;
      line_to(want, 1);
    }
    // The turn: straight back (a reversal), or a sharp corner.
    if (rng_.chance(0.8)) {
      const int64_t back = rng_.integer(1, m + 3);
      Vec want;
      for (int k = 0; k < 3; ++k) want[k] = exact ? start[k] + d[k] * h * (m - back) : pos_[k] - d[k] * h * back;
      line_to(want, 1);
    } else {
      const Vec e = direction(false);
      line_by({-d[0] / norm(d) + 0.2 * e[0], -d[1] / norm(d) + 0.2 * e[1], -d[2] / norm(d)}, h * n, 1);
    }
  }

  // KRN-6: contour parameters, the modal switches, or G61/G60 on the next
  // motion line (one block transition G function per block: 20117).
  void contour_switch(bool parameters_only) {
    const double dev = rng_.log_uniform(0.0005, 0.5), dist = rng_.log_uniform(0.001, 2);
    const std::string dev_text = num(std::round(dev * 1e6) / 1e6), dist_text = num(std::round(dist * 1e6) / 1e6);
    const size_t which = parameters_only ? rng_.pick({3.0, 1.0}) : rng_.pick({2, 1, 1, 1, 1, 1.5, 1, 1, 0.7, 0.7, 1.5, 1});
    switch (which) {
      case 0: emit("#CONTOUR MODE [DEV PATH_DEV=" + dev_text + "]"); break;
      case 1: emit("#CONTOUR MODE [DIST DIST=" + dist_text + "]"); break;
      case 2: emit("#CONTOUR MODE ON [DEV PATH_DEV=" + dev_text + "]"); break;
      case 3: emit("#CONTOUR MODE ON"); break;
      case 4: emit("#CONTOUR MODE OFF"); break;
      case 5: emit("G261"); break;
      case 6: emit("G260"); break;
      case 7: emit("#CONTOUR MODE ON [DEV, PATH_DEV = " + dev_text + "]"); break;
      case 8: emit("G360"); break;
      case 9: emit("G359"); break;
      case 10: transition_next_ = " G61"; break;
      default: transition_next_ = " G60"; break;
    }
  }

  // KRN-9: #HSC ON with parameters, now and then OFF, ON alone, or the
  // parameters alone.
  void hsc_command(bool on) {
    const double dev = rng_.log_uniform(0.001, 0.5);
    std::string list = "[BSPLINE PATH_DEV=" + num(std::round(dev * 1e6) / 1e6);
    if (rng_.chance(0.7)) list += " MERGE=" + std::string(rng_.chance(0.7) ? "1" : "0");
    if (rng_.chance(0.2)) list += " MAX_ANGLE=" + num(std::round(rng_.uniform(1, 90)));
    if (rng_.chance(0.15)) list += " AUTO_OFF_PATH=1";
    if (rng_.chance(0.15)) list += " AUTO_OFF_G00=1";
    if (rng_.chance(0.15)) list += " AUTO_OFF_G60=1";
    if (rng_.chance(0.15)) list += " MAX_PATH_LENGTH=" + num(std::round(rng_.log_uniform(0.01, 5) * 1e4) / 1e4);
    if (rng_.chance(0.1)) list += " TRACK_DEV=0";
    list += "]";
    const size_t which = on ? 0 : rng_.pick({3.0, 1.5, 1.0, 1.0});
    switch (which) {
      case 0: emit("#HSC ON " + list); break;
      case 1: emit("#HSC OFF"); break;
      case 2: emit("#HSC ON"); break;
      default: emit("#HSC " + list); break;
    }
  }

  // A CAM-style polyline: chords of a circle (or of a helix), from tiny to
  // half a millimetre, often at a high feed, now and then ending in a
  // reversal.
  void polyline() {
    const double r = rng_.log_uniform(0.2, 60);
    const double chord = std::min(rng_.log_uniform(0.001, 0.5), r / 2);
    const int n = static_cast<int>(rng_.integer(4, 80));
    const bool ccw = rng_.chance(0.5);
    const double dz = rng_.chance(0.2) ? rng_.uniform(-0.02, 0.02) : 0.0;
    if (rng_.chance(0.6)) {
      set_feed(std::round(rng_.log_uniform(1200, 15000)));
      feed_on_next_ = true;
    }
    const double heading = rng_.uniform(0, 2 * M_PI), side = ccw ? 1 : -1;
    const double cx = pos_[0] - side * r * std::sin(heading), cy = pos_[1] + side * r * std::cos(heading);
    const double a0 = std::atan2(pos_[1] - cy, pos_[0] - cx), step = side * 2 * std::asin(chord / (2 * r));
    for (int k = 1; k <= n; ++k) {
      Vec want{cx + r * std::cos(a0 + k * step), cy + r * std::sin(a0 + k * step), pos_[2] + dz};
      if (decimals_ > 0)  // as CAM writes them (KRN-9)
        for (double& w : want) w = std::round(w * std::pow(10.0, decimals_)) / std::pow(10.0, decimals_);
      line_to(want, 1);
    }
    if (rng_.chance(0.25)) line_by(direction(false), rng_.log_uniform(0.001, 1), 1);  // a corner
    if (rng_.chance(0.15)) {  // straight back
      const Vec back{cx + r * std::cos(a0 + (n - 1) * step), cy + r * std::sin(a0 + (n - 1) * step), pos_[2]};
      line_to(back, 1);
    }
  }

  // Lines that turn by a hair (1e-7 .. 1e-2 rad) at each joint.
  void nearly_straight() {
    double angle = rng_.uniform(0, 2 * M_PI);
    const int n = static_cast<int>(rng_.integer(3, 25));
    const double l = rng_.log_uniform(0.002, 3);
    for (int k = 0; k < n; ++k) {
      angle += (rng_.chance(0.5) ? 1 : -1) * rng_.log_uniform(1e-7, 1e-2);
      line_by({std::cos(angle), std::sin(angle), 0}, rng_.chance(0.8) ? l : rng_.log_uniform(0.002, 3), 1);
    }
    if (rng_.chance(0.3)) line_by({-std::cos(angle), -std::sin(angle), 0}, l, 1);  // reversal
  }

  void relative_section() {
    emit(rng_.chance(0.5) ? "G91" : "G91 F" + feed_word_);
    absolute_ = false;
    const int items = static_cast<int>(rng_.integer(1, 6));
    for (int i = 0; i < items; ++i) item(pick_item(true));
    emit("G90");
    absolute_ = true;
  }

  Rng rng_;
  ProgramOptions options_;
  const MachineConfig& machine_;
  uint64_t seed_ = 0;
  int ix_ = 0, iy_ = 1, iz_ = 2;
  GeneratedProgram out_;
  Vec pos_{0, 0, 0};
  bool absolute_ = true;
  bool in_lift_ = false;  // inside a lift range: Z is not programmed
  // An arc plane: its first and second axis, its normal (0 X, 1 Y, 2 Z) and
  // centre words (KRN-8).
  struct ArcPlane {
    int g, first, second, normal;
    char centre[2];
  };
  static constexpr ArcPlane g17{17, 0, 1, 2, {'I', 'J'}}, g18{18, 2, 0, 1, {'K', 'I'}}, g19{19, 1, 2, 0, {'J', 'K'}};
  ArcPlane plane_ = g17;
  double lift_pos_ = 0;   // where the open range lands
  double feed_ = 0;  // mm/s
  std::string feed_word_;
  bool feed_on_next_ = false;  // write F on the next motion line
  std::string extra_;          // words appended to the next motion line (M functions)
  std::string transition_next_;  // G61 or G60 for the next motion line (KRN-6)
  bool counting_ = true;
  double dps_ = 0;
  int decimals_ = 0;  // polylines rounded to this many decimals (hsc kind); 0: not rounded
};

}  // namespace

bool switches_contouring_on(const std::string& line) {
  for (const char* on : {"G261", "G61", "#CONTOUR MODE ON", "#HSC ON"})
    if (line.find(on) != std::string::npos) return true;
  return false;
}

bool switches_hsc_on(const std::string& line) { return line.find("#HSC ON") != std::string::npos; }

GeneratedProgram generate_program(uint64_t seed, const ProgramOptions& options, const MachineConfig& machine) {
  return Generator(seed, options, machine).run();
}

}  // namespace hil::fuzz
