#pragma once
// The channel's function lists P-STUP-00060 path_preparation.function and
// P-STUP-00070 interpolator.function ("FCT_DEFAULT | FCT_LIFT_UP_TIME")
// with P-CHAN-00345 enable_time_based_lift: which lift method the channel
// has (TF5200_lift_function.txt 4.2.1). The rig always has the functions
// of FCT_DEFAULT / FCT_IPO_DEFAULT; of the rest it has only the lift
// functions, and every other identifier of the two tables is refused by
// name.
#include <string>

#include "machine_config.hpp"

namespace hil {

struct FunctionLists {
  std::string path_preparation = "FCT_DEFAULT";        // P-STUP-00060
  std::string interpolator = "FCT_IPO_DEFAULT";        // P-STUP-00070
  int enable_time_based_lift = 0;                      // P-CHAN-00345, 0 or 1
};

// Throws ConfigError naming the parameters (`where`: the file's mapping,
// "machine") for an unknown or unsupported identifier, a malformed list
// and a contradiction between the three.
LiftMethod resolve_lift_method(const FunctionLists& lists, const std::string& where);

}  // namespace hil
