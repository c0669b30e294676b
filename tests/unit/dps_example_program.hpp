#pragma once
// TF5200_distance_from_program_start.txt's example program (DPS-2): its
// distances are [0, 100] .. [700, 800]; the starting movements after each
// G92 are left out (#DISTANCE PROG START OFF).
namespace hil::test {

inline constexpr const char* dps_example_program =
    "N10 #DISTANCE PROG START OFF\n"
    "N20 G01 G90 X0 Y0 Z0 F6000\n"
    "N100 G92 X33 Y55\n"
    "N110 X0 Y0 Z0\n"
    "N120 #DISTANCE PROG START ON\n"
    "N130 X100\n"
    "N140 Y100\n"
    "N150 X0\n"
    "N160 Y0\n"
    "N170 #DISTANCE PROG START OFF\n"
    "N200 G92 X600 Y700\n"
    "N210 X0 Y0 Z0\n"
    "N220 #DISTANCE PROG START ON\n"
    "N230 X100\n"
    "N240 Y100\n"
    "N250 X0\n"
    "N260 Y0\n"
    "N270 #DISTANCE PROG START OFF\n"
    "M30\n";

}  // namespace hil::test
