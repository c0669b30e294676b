#include "function_lists.hpp"

#include <algorithm>
#include <set>
#include <vector>

#include "config_error.hpp"

namespace hil {
namespace {

// One function table of TF5200_lift_function.txt 4.2.1: what the rig has,
// and what else the table lists (refused as not supported).
struct FunctionTable {
  const char* parameter;  // "P-STUP-00060 path_preparation_function"
  std::vector<std::string> supported;
  std::vector<std::string> unsupported;
  std::vector<std::string> defaults;  // one of these must be in the list
};

const FunctionTable path_preparation_table = {
    "P-STUP-00060 path_preparation_function",
    {"FCT_DEFAULT", "FCT_LIFT_UP", "FCT_LIFT_UP_TIME"},
    {"FCT_FFM", "FCT_PRESEGMENTATION", "FCT_SPLINE", "FCT_POLY", "FCT_CAX", "FCT_CAX_TRACK", "FCT_SEGMENTATION",
     "FCT_EMF", "FCT_EMF_POLY_OFF", "FCT_SYNC", "FCT_PRECON", "FCT_PTP", "FCT_M_PRE_OUTPUT", "FCT_SURFACE",
     "FCT_SEG_CHECK", "FCT_NIBBLING", "FCT_PUNCHING", "FCT_VSM"},
    {"FCT_DEFAULT"}};

// FCT_DEFAULT: the text's own examples write it in P-STUP-00070 too
// (2.1.2, P-CHAN-00345); FCT_LOOK_AHEAD_STANDARD is what FCT_IPO_DEFAULT
// holds (120 blocks, KRN-3).
const FunctionTable interpolator_table = {
    "P-STUP-00070 interpolator_function",
    {"FCT_IPO_DEFAULT", "FCT_DEFAULT", "FCT_LOOK_AHEAD_STANDARD", "FCT_LIFT_UP_TIME"},
    {"FCT_LOOK_AHEAD_LOW", "FCT_LOOK_AHEAD_HIGH", "FCT_LOOK_AHEAD_CUSTOM", "FCT_SYNC", "FCT_LOOK_AHEAD_OPT",
     "FCT_SHIFT_NCBL", "FCT_CALC_STATE_AT_T", "FCT_CALC_TIME", "FCT_CONTOUR_LAH", "FCT_DYN_POS_LIMIT",
     "FCT_EXTENSION_EQUIDIST", "FCT_CALC_POS_V_0", "FCT_DLM"},
    {"FCT_IPO_DEFAULT", "FCT_DEFAULT", "FCT_LOOK_AHEAD_STANDARD"}};

bool contains(const std::vector<std::string>& list, const std::string& item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}

// The identifiers of "A | B | C", each checked against `table`.
std::set<std::string> read_list(const std::string& text, const FunctionTable& table, const std::string& where) {
  const std::string at = where + ": " + table.parameter + " '" + text + "'";
  std::set<std::string> identifiers;
  for (size_t begin = 0;;) {
    const size_t bar = text.find('|', begin);
    std::string item = text.substr(begin, bar == std::string::npos ? std::string::npos : bar - begin);
    const size_t first = item.find_first_not_of(" \t");
    item = first == std::string::npos ? "" : item.substr(first, item.find_last_not_of(" \t") - first + 1);
    if (item.empty()) throw ConfigError(at + ": an empty identifier (identifiers joined by '|')");
    if (contains(table.unsupported, item))
      throw ConfigError(at + ": " + item + " is not supported by this rig");
    if (!contains(table.supported, item)) {
      std::vector<std::string> known = table.supported;
      known.insert(known.end(), table.unsupported.begin(), table.unsupported.end());
      const std::string nearest = closest_key(item, known);
      const std::string other = &table == &path_preparation_table ? " (an identifier of P-STUP-00070?)"
                                                                    : " (an identifier of P-STUP-00060?)";
      throw ConfigError(at + ": unknown identifier " + item +
                        (nearest.empty() ? other : ", did you mean " + nearest + "?"));
    }
    if (!identifiers.insert(item).second) throw ConfigError(at + ": " + item + " given twice");
    if (bar == std::string::npos) break;
    begin = bar + 1;
  }
  // The rig cannot deselect the functions it always has (contouring, look-ahead).
  if (std::none_of(table.defaults.begin(), table.defaults.end(),
                   [&](const std::string& d) { return identifiers.count(d) != 0; }))
    throw ConfigError(at + ": needs " + table.defaults.front() +
                      " (this rig cannot deselect the functions it holds)");
  return identifiers;
}

}  // namespace

LiftMethod resolve_lift_method(const FunctionLists& lists, const std::string& where) {
  const std::set<std::string> preparation = read_list(lists.path_preparation, path_preparation_table, where);
  const std::set<std::string> interpolator = read_list(lists.interpolator, interpolator_table, where);
  const bool lift_up = preparation.count("FCT_LIFT_UP") != 0;
  const bool time_preparation = preparation.count("FCT_LIFT_UP_TIME") != 0;
  const bool time_interpolator = interpolator.count("FCT_LIFT_UP_TIME") != 0;
  const bool time_based = lists.enable_time_based_lift == 1;
  const std::string at = where + ": ";
  if (lift_up && (time_preparation || time_interpolator))
    throw ConfigError(at + "FCT_LIFT_UP (Lifting) and FCT_LIFT_UP_TIME (Advanced Lifting) exclude each other in "
                           "P-STUP-00060 path_preparation_function / P-STUP-00070 interpolator_function");
  if (time_based && !(time_preparation && time_interpolator))
    throw ConfigError(at + "P-CHAN-00345 enable_time_based_lift = 1 needs FCT_LIFT_UP_TIME in both "
                           "P-STUP-00060 path_preparation_function and P-STUP-00070 interpolator_function");
  if ((time_preparation || time_interpolator) && !time_based)
    throw ConfigError(at + "FCT_LIFT_UP_TIME in P-STUP-00060 path_preparation_function / P-STUP-00070 "
                           "interpolator_function needs P-CHAN-00345 enable_time_based_lift = 1");
  if (time_based) return LiftMethod::time_based;
  if (lift_up) return LiftMethod::path_based;
  return LiftMethod::none;
}

}  // namespace hil
