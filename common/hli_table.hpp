#pragma once
// The HLI's fields, one table (KRN-4). Each list is X(type, name):
//  - name: the TF5200 name, the member of HliControl / HliState (hli.hpp)
//    and of the LCM type (lcmtypes/hli_control_t.lcm, hli_state_t.lcm);
//  - type: the type the TF5200 texts give it: BOOL bool, DINT int32_t,
//    UDINT uint32_t (an int64_t in the .lcm: LCM has no unsigned types);
//    a per-axis BOOL (gpAx[axis_idx]^...) std::vector<bool>, in the .lcm
//    boolean[n_axes].
// From these lists come the members, the LCM conversion
// (lcm_support/messages.cpp, checked at compile time against the .lcm) and
// the names scenarios read and write (hli_names.hpp: "unit.command_w", every
// BOOL / DINT / UDINT / LINT field; a per-axis BOOL by axis name).
// docs/ARCHITECTURE.md ("The HLI table") says how to add a control unit.

// A control unit as the PLC writes it (MC_CONTROL_*_UNIT; Command is its
// command_w's type) and as the CNC answers it (State: state_r's type).
#define HLI_CONTROL_UNIT_FIELDS(X) \
  X(Command, command_w)            \
  X(bool, enable_w)
#define HLI_STATE_UNIT_FIELDS(X) \
  X(bool, request_r)             \
  X(State, state_r)

// The insert command unit (TF5200_insert_stop_cmd.txt, ISC-1, ISC-2):
// MC_CONTROL_INSERT_CMD_UNIT as the PLC writes it, HLI_INSERT_CMD_COMMAND,
// and the CNC's answer, HLI_INSERT_CMD_STATE. UINT is uint16_t, LREAL double.
#define HLI_INSERT_CMD_COMMAND_FIELDS(X)                                            \
  X(double, dist_or_pos)      /* 0.1 um: distance (axis_nr 0) or axis position */ \
  X(uint16_t, rel_abs_mode)   /* 0 relative iterative, 1 absolute, 2 relative once */ \
  X(uint16_t, axis_nr)        /* 0 DISTANCE mode; > 0 POSITION mode, logical axis */ \
  X(uint16_t, m_function_nr)  /* 0 M00, 1 M01, > 1 M<n> (MVS_SVS) */                 \
  X(int32_t, add_nr)          /* the M function's additional value */
#define HLI_INSERT_CMD_STATE_FIELDS(X)                                                  \
  X(double, distance_of_next_stop) /* 0.1 um dist_prog_start at the next stop; -1 not found */ \
  X(StopPositions, position_at_next_stop) /* 0.1 um: X Y Z (DISTANCE) or [0] the axis (POSITION) */ \
  X(int32_t, state)                /* 0 no stop commanded, 1 commanded, not reached */
#define HLI_INSERT_CMD_UNIT_FIELDS(X) \
  X(InsertCmdCommand, command_w)      \
  X(bool, enable_w)                   \
  X(bool, semaphor_rw) /* consumption: the PLC sets it with new data, the CNC clears it */
#define HLI_INSERT_CMD_UNIT_STATE_FIELDS(X) \
  X(bool, semaphor_rw) /* the CNC's side: FALSE once it has read command_w */ \
  X(InsertCmdState, state_r)

// The block search unit (DPS-3, TF5200_distance_from_program_start.txt):
// set before program start; the start then runs the search and continues
// the program there (docs/BLOCK_SEARCH.md).
#define HLI_BLOCK_SEARCH_COMMAND_FIELDS(X)                                                 \
  X(uint32_t, type)      /* UDINT: 1 at the block's start, 4 block number + covered distance */ \
  X(uint32_t, block_nr)  /* UDINT: N number of the block searched (its first in the program) */ \
  X(double, distance)    /* LREAL, 0.1 um: dist_prog_start at the continuation point (type 4) */
#define HLI_BLOCK_SEARCH_STATE_FIELDS(X)                                                          \
  X(int32_t, state)  /* 0 none, 1 repositioning, 2 continued, 3 error (the program did not start) */ \
  X(bool, continuation_moved) /* the distance lay before the block: it continues at its start */  \
  X(uint32_t, continuation_block_nr)  /* N of the block the continuation point lies in */          \
  X(int64_t, continuation_nc_line)    /* its NC program line */                                    \
  X(double, continuation_distance)    /* 0.1 um: dist_prog_start at the continuation point */

// A zero offset table entry as the PLC writes it (KRN-8; TwinCAT: the zero
// offset data np_grp[group].achse[axis].versch, written over ADS). UINT is
// uint16_t, LREAL double.
#define HLI_ZERO_OFFSET_COMMAND_FIELDS(X)                              \
  X(uint16_t, group)    /* 1 .. 6: G54 .. G59 */                      \
  X(uint16_t, axis_nr)  /* 1 = the first machine axis */              \
  X(double, value)      /* 0.1 um (0.0001 deg on a rotary axis) */

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
  /* The same for an H function, an S (spindle speed) and a T (tool) (KRN-8). */      \
  X(ControlUnitBool, h_function_ack)                                                   \
  X(ControlUnitBool, s_function_ack)                                                   \
  X(ControlUnitBool, t_function_ack)                                                   \
  /* Backward motion on the path (bahn_mc_control.backward_motion, KRN-5), a level; */ \
  /* without P-STUP-00033 a request holds the path until withdrawn (DDTG-10). */       \
  X(ControlUnitBool, backward_motion)                                                  \
  /* Insert stop marks (ISC-1): command_w read when semaphor_rw while enable_w. */     \
  X(InsertCmdUnit, insert_cmd)                                                         \
  /* Rising edge of command_w while enable_w leaves an M00 / M01 stop (ISC-5). */      \
  X(ControlUnitBool, continue_motion)                                                  \
  /* command_w while enable_w: M01 stops (optional stop, ISC-5). */                    \
  X(ControlUnitBool, m01_stop_enable)                                                  \
  /* Rising edge of command_w while enable_w, the path standing: the program is */     \
  /* aborted and the channel is READY for a new start (docs/BLOCK_SEARCH.md). */         \
  X(ControlUnitBool, reset)                                                            \
  /* enable_w at the program start's edge: the start searches command_w (DPS-3). */     \
  X(ControlUnitBlockSearch, block_search)                                             \
  /* decoder_mc_control.program_block_ignore (KRN-8): skip levels, bit 0 /1 .. */      \
  /* bit 9 /10, while enable_w; read by the decoder line by line. */                  \
  X(ControlUnitUns32, program_block_ignore)                                           \
  /* A new command_w while enable_w sets one G54..G59 table entry; blocks */        \
  /* decoded from then on use it (KRN-8). */                                         \
  X(ControlUnitZeroOffset, zero_offset)

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
  /* Per axis (ipo_state, LIFT-7): the axis lifts (LIFT_START .. LIFT_END); */       \
  /* the lift is suppressed (path shorter than P-CHAN-00244, LIFT-4). */              \
  X(std::vector<bool>, lift_active)                                                  \
  X(std::vector<bool>, lift_suppressed)                                              \
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
  X(int32_t, m_function_add_nr_r)  /* its additional value (insert stop add_nr) */   \
  /* H<nr>, S<rpm> (with M03 / M04 or while the spindle turns), T<tool>, each */     \
  /* output and acknowledged the same way (KRN-8); D<nr>: the tool offset in */      \
  /* force, no handshake. */                                                         \
  X(bool, h_function_request_r)                                                      \
  X(int32_t, h_function_nr_r)                                                        \
  X(bool, s_function_request_r)                                                      \
  X(double, s_function_value_r)    /* rpm */                                         \
  X(bool, t_function_request_r)                                                      \
  X(int32_t, t_function_nr_r)                                                        \
  X(int32_t, tool_offset_nr_r)                                                       \
  X(ControlUnitState, backward_motion) /* state_r: moving backward */                \
  X(InsertCmdUnitState, insert_cmd)    /* ISC-1, ISC-2 */                            \
  X(ControlUnitState, continue_motion) /* state_r: the edge was taken */             \
  X(ControlUnitState, m01_stop_enable) /* state_r: M01 stops */               \
  X(ControlUnitState, reset)           /* state_r: the edge was taken */       \
  X(ControlUnitBlockSearchState, block_search) /* DPS-3 */                     \
  X(ControlUnitUns32State, program_block_ignore) /* state_r: skip levels in force */
