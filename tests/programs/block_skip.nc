%block_skip
; --------------------------------------------------------------------------
; block_skip.nc
;
; What:    face milling with optional blocks: /N.. M01 (measuring stop) and /1
;          N.. finishing pass (both skip level 1: a bare / is level 1), /2 N..
;          wall spring pass; each option ends where the program goes on, so
;          every combination of skip levels is a valid path.
; Style:   hand-written shop-floor program: N10 step 10, ; notes, every word
;          repeated after the optional blocks.
; Origin:  written for this project in the style of a hand-written shop-floor
;          program, 2026
; Machine: config/xyz_machine.yaml: axes X Y Z, no rotary (runs unchanged on
;          config/xyzc_machine.yaml, C not programmed)
; Offsets: zero offsets of the machine file (zero_offsets): G54 = X100 Y50
;          Z-20, G55 = X300 Y50 Z-20 (machine = program + offset)
; Time:    ~16.3 s of motion (14.7 s feed over 500 mm, 1.7 s rapid) + 0.0 s
;          dwell, estimated as path length / feed
; Skips:   with every skip level on: 6.3 s of motion; every combination of
;          levels checked
; --------------------------------------------------------------------------
; face 40 x 20 at Z-1 with an end mill D12, then options:
;   skip level 1 (/ and /1): roughing only - no M01 measuring stop, no finishing pass at Z-1.2
;   skip level 2 (/2):       no spring pass round the stock walls at Z-3
N10 G90 G71 G17 G40 G94
N20 G54
N30 T6 M06
N40 D6
N50 S6000 M03
N60 M08
; roughing the face
N70 G00 X-8 Y4
N80 Z5
N90 G01 Z-1 F600
N100 X48 F2400
N110 Y12
N120 X-8
N130 Y20
N140 X48
N150 G00 Z5
; optional stop: measure the face depth
/N160 M01
; optional finishing pass
/1 N170 G00 X-8 Y4
/1 N180 G01 Z-1.2 F600
/1 N190 X48 F2000
/1 N200 Y20
/1 N210 X-8
/1 N220 G00 Z5
; optional spring pass round the stock 40 x 20 (tool centre 6 outside the walls)
/2 N230 G00 X-6 Y-6
/2 N240 G01 Z-3 F600
/2 N250 X46 F2400
/2 N260 Y26
/2 N270 X-6
/2 N280 Y-6
/2 N290 G00 Z5
N300 G00 Z50
N310 M09
N320 M05
N330 X0 Y100
N340 M30
