%inch_program
; --------------------------------------------------------------------------
; inch_program.nc
;
; What:    small profile and bore in G70 (inch): inch coordinates with leading
;          dots (X-.125, I.375), inch/min feeds F20..F80, a full circle
;          starting at 30 deg; G71 again near the end for metric park moves.
; Style:   Mastercam-like inch post converted to the TwinCAT words
;          (inch/metric as G70/G71, tool offset as D).
; Origin:  written for this project in the style of Mastercam (inch) output,
;          2026
; Machine: config/xyz_machine.yaml: axes X Y Z, no rotary (runs unchanged on
;          config/xyzc_machine.yaml, C not programmed)
; Offsets: zero offsets of the machine file (zero_offsets): G54 = X100 Y50
;          Z-20, G55 = X300 Y50 Z-20 (machine = program + offset)
; Time:    ~12.9 s of motion (11.5 s feed over 290 mm, 1.4 s rapid) + 0.0 s
;          dwell, estimated as path length / feed
; --------------------------------------------------------------------------
(PROGRAM NAME - INCH_PROGRAM)
(DATE=DD-MM-YY - 02-03-26 TIME=HH:MM - 14:05)
(MATERIAL - ALUMINUM INCH - 6061)
( T7 |  0.25 IN FLAT ENDMILL | H7 | D7 )
(STOCK - 2.0 X 1.5 X .5 - ZERO LOWER LEFT TOP)
N100 G70 G00 G17 G40 G90 G94
N102 T7 M06
N104 G90 G54 G00 X-.5 Y-.25 S10000 M03
N106 D7 Z1 M08
N108 Z.1
N110 G01 Z-.15 F20
N112 X-.125 F80
N114 Y1.25
N116 G02 X.25 Y1.625 I.375
N118 G01 X1.75
N120 G02 X2.125 Y1.25 J-.375
N122 G01 Y.25
N124 G02 X1.75 Y-.125 I-.375
N126 G01 X.25
N128 G02 X-.125 Y.25 J.375
N130 G01 Y.5
N132 X-.375
N134 G00 Z.1
(BORE D.75 AT X1. Y.75 - PRE-DRILLED)
N136 X1 Y.75
N138 G01 Z-.25 F20
N140 X1.2165 Y.875 F40
N142 G03 X1.2165 Y.875 I-.2165 J-.125
N144 G01 X1 Y.75
N146 G00 Z1
N148 M09
N150 M05
(BACK TO METRIC FOR THE PARK POSITION)
N152 G71
N154 G00 Z50
N156 X0 Y100
N158 M30
