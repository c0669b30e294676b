#include "drive_monitor.hpp"

#include <cmath>
#include <sstream>

namespace hil::axis {

DriveMonitor::DriveMonitor(const AxisConfig& axis) : axis_(axis) {}

MonitorState DriveMonitor::check(const DriveSample& s, std::vector<Event>& events) {
  MonitorState now;
  // One event per monitor and severity when its limit is first exceeded;
  // its text is made only then (every cycle, it would cost more than the drive).
  auto test = [&](int32_t bit, Severity severity, bool exceeded, const char* parameter, double value,
                  double limit, const auto& what) {
    if (!exceeded) return;
    int32_t& bits = severity == Severity::error ? now.errors : now.warnings;
    const int32_t before = severity == Severity::error ? previous_.errors : previous_.warnings;
    if (bits & bit) return;  // counted this cycle already (the other side of a limit pair)
    bits |= bit;
    if (before & bit) return;  // the same excursion
    Event e;
    e.severity = severity;
    e.parameter = parameter;
    e.axis = axis_.name;
    e.value = value;
    e.limit = limit;
    e.message = what();
    events.push_back(e);
  };
  auto text = [](auto... parts) {
    std::ostringstream o;
    (o << ... << parts);
    return o.str();
  };

  const bool finite = std::isfinite(s.setpoint_position) && std::isfinite(s.setpoint_velocity) &&
                      std::isfinite(s.position) && std::isfinite(s.velocity) && std::isfinite(s.acceleration);
  test(monitor::not_finite, Severity::error, !finite, "", s.setpoint_position, 0,
       [&] { return text("setpoint position ", s.setpoint_position, " mm / velocity ", s.setpoint_velocity,
            " mm/s is not a finite number; the drive holds its last valid setpoint"); });

  const double a = std::abs(s.acceleration);
  const double a_warn = axis_.accel_warning_limit(), a_err = axis_.accel_error_limit();
  test(monitor::acceleration, Severity::warning, a > a_warn, "P-AXIS-00441", s.acceleration, a_warn,
       [&] { return text("acceleration ", s.acceleration, " mm/s^2 exceeds ", a_warn, " mm/s^2 (a_max ", axis_.a_max,
            " * P-AXIS-00441 ", axis_.dyn_monitoring_a_warn, " / 1000)"); });
  test(monitor::acceleration, Severity::error, a > a_err, "P-AXIS-00442", s.acceleration, a_err,
       [&] { return text("acceleration ", s.acceleration, " mm/s^2 exceeds ", a_err, " mm/s^2 (a_max ", axis_.a_max,
            " * P-AXIS-00442 ", axis_.dyn_monitoring_a_err, " / 1000)"); });

  const double v = std::abs(s.velocity);
  const double v_warn = axis_.velocity_warning_limit(), v_err = axis_.velocity_error_limit();
  test(monitor::velocity, Severity::warning, v > v_warn, "P-AXIS-00439", s.velocity, v_warn,
       [&] { return text("velocity ", s.velocity, " mm/s exceeds ", v_warn, " mm/s (v_max ", axis_.v_max, " * P-AXIS-00439 ",
            axis_.dyn_monitoring_v_warn, " / 1000)"); });
  test(monitor::velocity, Severity::error, v > v_err, "P-AXIS-00440", s.velocity, v_err,
       [&] { return text("velocity ", s.velocity, " mm/s exceeds ", v_err, " mm/s (v_max ", axis_.v_max, " * P-AXIS-00440 ",
            axis_.dyn_monitoring_v_err, " / 1000)"); });

  if (axis_.following_error_monitoring == 4) {
    const bool moving = s.setpoint_velocity != 0;
    const double limit = moving ? axis_.slep_max : axis_.slep_min;
    const char* parameter = moving ? "P-AXIS-00168" : "P-AXIS-00169";
    test(monitor::following_error, Severity::error, std::abs(s.following_error) > limit, parameter,
         s.following_error, limit,
         [&] { return text("following error ", s.following_error, " mm exceeds ", parameter, moving ? " slep_max " : " slep_min ",
              limit, " mm (", moving ? "moving" : "at standstill", ", P-AXIS-00172 type 4)"); });
  }

  if (axis_.software_limits) {
    const double pos_actual = axis_.swe_pos + axis_.swe_toleranz, neg_actual = axis_.swe_neg - axis_.swe_toleranz;
    test(monitor::software_limit, Severity::error, s.setpoint_position > axis_.swe_pos, "P-AXIS-00178",
         s.setpoint_position, axis_.swe_pos,
         [&] { return text("setpoint ", s.setpoint_position, " mm beyond the positive software limit switch P-AXIS-00178 swe_pos ",
              axis_.swe_pos, " mm"); });
    test(monitor::software_limit, Severity::error, s.setpoint_position < axis_.swe_neg, "P-AXIS-00177",
         s.setpoint_position, axis_.swe_neg,
         [&] { return text("setpoint ", s.setpoint_position, " mm beyond the negative software limit switch P-AXIS-00177 swe_neg ",
              axis_.swe_neg, " mm"); });
    test(monitor::software_limit, Severity::error, s.position > pos_actual, "P-AXIS-00178", s.position, pos_actual,
         [&] { return text("actual position ", s.position, " mm beyond P-AXIS-00178 swe_pos + P-AXIS-00179 swe_toleranz = ",
              pos_actual, " mm"); });
    test(monitor::software_limit, Severity::error, s.position < neg_actual, "P-AXIS-00177", s.position, neg_actual,
         [&] { return text("actual position ", s.position, " mm beyond P-AXIS-00177 swe_neg - P-AXIS-00179 swe_toleranz = ",
              neg_actual, " mm"); });
  }
  previous_ = now;
  return now;
}

}  // namespace hil::axis
