#pragma once
// The HLI's fields, one table (KRN-4). Each list is X(type, name):
//  - name: the TF5200 name, the member of HliControl / HliState (hli.hpp)
//    and of the LCM type (lcmtypes/hli_control_t.lcm, hli_state_t.lcm);
//  - type: the type the TF5200 texts give it: BOOL bool, DINT int32_t,
//    UDINT uint32_t (an int64_t in the .lcm: LCM has no unsigned types).
// From these lists come the members, the LCM conversion
// (lcm_support/messages.cpp, checked at compile time against the .lcm) and
// the names scenarios read and write (hli_names.hpp: "unit.command_w", every
// BOOL / DINT / UDINT / LINT field). docs/ARCHITECTURE.md ("The HLI table")
// says how to add a control unit.

// A control unit as the PLC writes it (MC_CONTROL_*_UNIT; Command is its
// command_w's type) and as the CNC answers it (State: state_r's type).
#define HLI_CONTROL_UNIT_FIELDS(X) \
  X(Command, command_w)            \
  X(bool, enable_w)
#define HLI_STATE_UNIT_FIELDS(X) \
  X(bool, request_r)             \
  X(State, state_r)

// PLC -> CNC (hli_control_t), applied by the CNC one cycle later (RIG-6).
#define HLI_CONTROL_UNITS(X)                                                           \
  /* Rising edge of command_w while enable_w starts the NC program. */                 \
  X(ControlUnitBool, program_start)                                                    \
  /* command_w while enable_w: stop on the path, jerk-limited; resume on release. */   \
  X(ControlUnitBool, feedhold)                                                         \
  /* Path override in 0.1 % (1000 = 100 %) while enable_w; 100 % otherwise. */         \
  X(ControlUnitValue, override)                                                        \
  /* Rising edge of command_w while enable_w: delete distance to go (DDTG-1). */       \
  X(ControlUnitBool, delete_distance_to_go)                                            \
  /* UDINT mask that makes #DEL DIST2GO [END=..] markers valid (DDTG-5). */            \
  X(ControlUnitUns32, delete_distance_to_go_activation)                                \
  /* Rising edge of command_w while enable_w acknowledges the M function the CNC */    \
  /* waits for (m_function_request_r). */                                              \
  X(ControlUnitBool, m_function_ack)                                                   \
  /* Backward motion on the path (bahn_mc_control.backward_motion, KRN-5), a level; */ \
  /* without P-STUP-00033 a request holds the path until withdrawn (DDTG-10). */       \
  X(ControlUnitBool, backward_motion)

// CNC -> PLC (hli_state_t), once per cycle. HLI lengths in 0.1 um.
// block_nr_r and block_count_r are UDINT in the texts: int64_t holds them all.
#define HLI_STATE_FIELDS(X)                                                          \
  X(ChannelState, channel_state)                                                     \
  X(int64_t, block_nr_r)      /* N number of the block in the interpolator */        \
  X(int64_t, block_count_r)   /* NC program line of the block in the interpolator */ \
  X(int32_t, stop_conditions_r) /* DINT, bits of hil::stop_condition */              \
  X(double, dist_prog_start)  /* 0.1 um, path covered since program start */         \
  X(double, path_velocity)    /* mm/s */                                             \
  X(int32_t, last_error_id)   /* TF5200 ID of the last error, 0 = none */            \
  X(std::vector<std::string>, axis_name)                                             \
  X(std::vector<int64_t>, axis_position_r) /* 0.1 um, commanded position */          \
  X(ControlUnitState, program_start)                                                 \
  X(ControlUnitState, feedhold)              /* state_r: feed hold in force */       \
  X(ControlUnitValueState, override)         /* state_r: override in force, 0.1 % */ \
  X(ControlUnitState, delete_distance_to_go) /* state_r: the command was detected */ \
  X(ControlUnitUns32State, delete_distance_to_go_activation)                         \
  X(bool, delete_distance_to_go_active_r)    /* a short cut runs (DDTG-4) */         \
  /* An M function is output and the path waits for the PLC's acknowledgement */     \
  /* (MVS_SVS); its number. */                                                       \
  X(bool, m_function_request_r)                                                      \
  X(int32_t, m_function_nr_r)                                                        \
  X(ControlUnitState, backward_motion) /* state_r: moving backward */
