#pragma once
// The whole-program decoder of before issue 17, frozen: the reference for
// the streamed decoder's tests (stream_decode_test.cpp).
#include <cstdint>
#include <string>
#include <vector>

#include "decoder.hpp"
#include "event.hpp"
#include "machine_config.hpp"

namespace hil::cnc::reference {

DecodedProgram whole_decode_program(const std::string& text, const MachineConfig& machine,
                                    const std::vector<double>& start);
DecodedProgram whole_decode_program(const std::string& text, const MachineConfig& machine,
                                    const std::vector<double>& start, int64_t max_lines_read);
std::vector<Block> whole_m_pre_output(std::vector<Block> blocks, const MachineConfig& machine,
                                      std::vector<Event>& warnings);

}  // namespace hil::cnc::reference
