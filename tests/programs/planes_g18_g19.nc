; --------------------------------------------------------------------------
; planes_g18_g19.nc
;
; What:    side work with a ball nose: a cove R10 cut in G18 (Z-X plane, arcs
;          with I K, G02 and G03 passes, 129 deg arcs with irrational end
;          points), a round-over R5 on the front edge in G19 (Y-Z plane, J K),
;          back to G17 for a ring G03 I J; explicit G162.
; Style:   hand-written shop-floor program: N10 step 10, short numbers, zero
;          centre words omitted, ; notes.
; Origin:  written for this project in the style of a hand-written shop-floor
;          program, 2026
; Machine: config/xyz_machine.yaml: axes X Y Z, no rotary (runs unchanged on
;          config/xyzc_machine.yaml, C not programmed)
; Offsets: zero offsets of the machine file (zero_offsets): G54 = X100 Y50
;          Z-20, G55 = X300 Y50 Z-20 (machine = program + offset)
; Time:    ~18.1 s of motion (16.3 s feed over 276 mm, 1.8 s rapid) + 0.0 s
;          dwell, estimated as path length / feed
; --------------------------------------------------------------------------
; part 60 x 40 x 20, top Z0, zero: front left top corner (G54)
; T5 ball nose D6 - D5 holds the length to the ball CENTRE: programmed points = ball centre
N10 G90 G71 G17 G40 G94 G162
N20 G54
N30 T5 M06
N40 D5
N50 S9000 M03
N60 M08
; --- cove R10 across X 12..28, 4 deep, along Y: G18, ball centre on R7 around X20 Z6
N70 G00 X13.675 Y6
N80 Z10
N90 G18
N100 Z5
N110 G01 Z3 F600
N120 G02 X26.325 Z3 K3 I6.325 F1200
N130 G00 Z5
N140 Y10
N150 G01 Z3 F600
N160 G03 X13.675 Z3 K3 I-6.325 F1200
N170 G00 Z5
N180 Y14
N190 G01 Z3 F600
N200 G02 X26.325 Z3 K3 I6.325 F1200
N210 G00 Z5
N220 Y18
N230 G01 Z3 F600
N240 G03 X13.675 Z3 K3 I-6.325 F1200
N250 G00 Z5
N260 Y22
N270 G01 Z3 F600
N280 G02 X26.325 Z3 K3 I6.325 F1200
N290 G00 Z5
N300 Y26
N310 G01 Z3 F600
N320 G03 X13.675 Z3 K3 I-6.325 F1200
N330 G00 Z5
N340 Y30
N350 G01 Z3 F600
N360 G02 X26.325 Z3 K3 I6.325 F1200
N370 G00 Z5
N380 Y34
N390 G01 Z3 F600
N400 G03 X13.675 Z3 K3 I-6.325 F1200
N410 G00 Z10
; --- round-over R5 on the front top edge (Y0 Z0), G19: ball centre on R8 around Y5 Z-5
N420 G19
N430 X4 Y-8
N440 Z-5
N450 G01 Y-3 F600
N460 G02 Y5 Z3 J8 F1200
N470 G00 Z6
N480 X16
N490 G01 Z3 F600
N500 G03 Y-3 Z-5 K-8 F1200
N510 G01 Y-8 F1500
N520 G00 X28
N530 G01 Y-3 F600
N540 G02 Y5 Z3 J8 F1200
N550 G00 Z6
N560 X40
N570 G01 Z3 F600
N580 G03 Y-3 Z-5 K-8 F1200
N590 G01 Y-8 F1500
N600 G00 X52
N610 G01 Y-3 F600
N620 G02 Y5 Z3 J8 F1200
N630 G00 Z10
; --- back to G17: R6 ring 0.5 deep round the mark at X47 Y28
N640 G17
N650 X53 Y28
N660 Z5
N670 G01 Z2.5 F300
N680 G03 X53 Y28 I-6 F1000
N690 G00 Z50
N700 M09
N710 M05
N720 M30
