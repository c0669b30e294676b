#include "decoder.hpp"

#include "line_source.hpp"
#include "program_decoder.hpp"

namespace hil::cnc {

DecodedProgram decode_program(const std::string& text, const MachineConfig& machine,
                              const std::vector<double>& start) {
  return decode_program(text, machine, start, ProgramDecoder::default_max_lines_read);
}

DecodedProgram decode_program(const std::string& text, const MachineConfig& machine, const std::vector<double>& start,
                              int64_t max_lines_read) {
  ProgramDecoder decoder(std::make_unique<StringLines>(text), machine, start, max_lines_read);
  DecodedProgram program;
  Block block;
  while (decoder.next(block)) program.blocks.push_back(std::move(block));
  program.error = decoder.error();
  return program;
}

}  // namespace hil::cnc
