; --------------------------------------------------------------------------
; incremental_g91.nc
;
; What:    a slot repeated 6 times: each slot in G91 (G01 and G03 I J
;          incremental), pattern origins set with G90 G92 X.. Y.. and moved
;          with G91 G92 X.. (the additive reference point offset of TwinCAT),
;          reset with G90 G92 X0 Y0; on top of G54.
; Style:   hand-written shop-floor program: N10 step 10, whole numbers, the
;          slot block-for-block the same.
; Origin:  written for this project in the style of a hand-written shop-floor
;          program, 2026
; Machine: config/xyz_machine.yaml: axes X Y Z, no rotary (runs unchanged on
;          config/xyzc_machine.yaml, C not programmed)
; Offsets: zero offsets of the machine file (zero_offsets): G54 = X100 Y50
;          Z-20, G55 = X300 Y50 Z-20 (machine = program + offset)
; Time:    ~12.8 s of motion (10.9 s feed over 254 mm, 1.8 s rapid) + 0.0 s
;          dwell, estimated as path length / feed
; --------------------------------------------------------------------------
; 6 rounded slots 12 x 10 (tool path, corner R3), D3 end mill, 1.5 deep
; each slot in G91 from its start point; G92 moves the pattern origin:
;   G90 G92 X.. Y.. sets the reference point offset, G91 G92 X.. adds to it
N10 G90 G71 G17 G40 G94
N20 G54
N30 T8 M06
N40 D8
N50 S9000 M03
N60 M08
N70 G00 Z10
N80 G90 G92 X10 Y10
N90 G90 G00 X3 Y0
N100 Z2
N110 G91 G01 Z-3.5 F400
N120 X6 F1800
N130 G03 X3 Y3 I0 J3
N140 G01 Y4
N150 G03 X-3 Y3 I-3 J0
N160 G01 X-6
N170 G03 X-3 Y-3 I0 J-3
N180 G01 Y-4
N190 G03 X3 Y-3 I3 J0
N200 G00 Z3.5
N210 G91 G92 X22
N220 G90 G00 X3 Y0
N230 Z2
N240 G91 G01 Z-3.5 F400
N250 X6 F1800
N260 G03 X3 Y3 I0 J3
N270 G01 Y4
N280 G03 X-3 Y3 I-3 J0
N290 G01 X-6
N300 G03 X-3 Y-3 I0 J-3
N310 G01 Y-4
N320 G03 X3 Y-3 I3 J0
N330 G00 Z3.5
N340 G91 G92 X22
N350 G90 G00 X3 Y0
N360 Z2
N370 G91 G01 Z-3.5 F400
N380 X6 F1800
N390 G03 X3 Y3 I0 J3
N400 G01 Y4
N410 G03 X-3 Y3 I-3 J0
N420 G01 X-6
N430 G03 X-3 Y-3 I0 J-3
N440 G01 Y-4
N450 G03 X3 Y-3 I3 J0
N460 G00 Z3.5
N470 G91 G92 X-44 Y18
N480 G90 G00 X3 Y0
N490 Z2
N500 G91 G01 Z-3.5 F400
N510 X6 F1800
N520 G03 X3 Y3 I0 J3
N530 G01 Y4
N540 G03 X-3 Y3 I-3 J0
N550 G01 X-6
N560 G03 X-3 Y-3 I0 J-3
N570 G01 Y-4
N580 G03 X3 Y-3 I3 J0
N590 G00 Z3.5
N600 G91 G92 X22
N610 G90 G00 X3 Y0
N620 Z2
N630 G91 G01 Z-3.5 F400
N640 X6 F1800
N650 G03 X3 Y3 I0 J3
N660 G01 Y4
N670 G03 X-3 Y3 I-3 J0
N680 G01 X-6
N690 G03 X-3 Y-3 I0 J-3
N700 G01 Y-4
N710 G03 X3 Y-3 I3 J0
N720 G00 Z3.5
N730 G91 G92 X22
N740 G90 G00 X3 Y0
N750 Z2
N760 G91 G01 Z-3.5 F400
N770 X6 F1800
N780 G03 X3 Y3 I0 J3
N790 G01 Y4
N800 G03 X-3 Y3 I-3 J0
N810 G01 X-6
N820 G03 X-3 Y-3 I0 J-3
N830 G01 Y-4
N840 G03 X3 Y-3 I3 J0
N850 G00 Z3.5
N860 G90 G92 X0 Y0
N870 G90 G00 Z50
N880 M09
N890 M05
N900 X0 Y100
N910 M30
