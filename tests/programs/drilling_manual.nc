; --------------------------------------------------------------------------
; drilling_manual.nc
;
; What:    drilling without cycles: G00 positioning, G01 Z feed, G04 dwell at
;          depth, G00 retract, a chip-break peck; 4 holes in G54 and 4 on a
;          bolt circle in G55 (irrational positions), spot drill T11 and drill
;          T12; ends with G53 (zero offset suppressed) moves.
; Style:   generic DIN 66025 post with drilling cycles output long-hand: N10
;          step 10, 3 decimals.
; Origin:  written for this project in the style of a generic DIN 66025 post
;          (drilling cycles written out long-hand), 2026
; Machine: config/xyz_machine.yaml: axes X Y Z, no rotary (runs unchanged on
;          config/xyzc_machine.yaml, C not programmed)
; Offsets: zero offsets of the machine file (zero_offsets): G54 = X100 Y50
;          Z-20, G55 = X300 Y50 Z-20 (machine = program + offset)
; Time:    ~17.8 s of motion (10.6 s feed over 100 mm, 7.2 s rapid) + 4.0 s
;          dwell, estimated as path length / feed
; --------------------------------------------------------------------------
(PLATE A in G54: 4 holes D6.8 on a 40 x 20 rectangle)
(PLATE B in G55: 4 holes D6.8 on PCD 40 at 45 deg)
(drill cycles output long-hand: G00 positioning - G01 feed - G04 dwell - G00 retract)
N10 G90 G71 G17 G40 G94
(T11 NC SPOT DRILL D10 90 DEG)
N20 T11 M06
N30 D11
N40 S4000 M03
N50 M08
N60 G54
N70 G00 X10 Y10
N80 Z25
N90 Z2
N100 G01 Z-1.5 F500
N110 G04 X0.3
N120 G00 Z2
N130 X50
N140 G01 Z-1.5
N150 G04 X0.3
N160 G00 Z2
N170 Y30
N180 G01 Z-1.5
N190 G04 X0.3
N200 G00 Z2
N210 X10
N220 G01 Z-1.5
N230 G04 X0.3
N240 G00 Z2
N250 Z25
N260 G55
N270 G00 X44.142 Y44.142
N280 Z2
N290 G01 Z-1.5 F500
N300 G04 X0.3
N310 G00 Z2
N320 X15.858
N330 G01 Z-1.5
N340 G04 X0.3
N350 G00 Z2
N360 Y15.858
N370 G01 Z-1.5
N380 G04 X0.3
N390 G00 Z2
N400 X44.142
N410 G01 Z-1.5
N420 G04 X0.3
N430 G00 Z2
N440 Z50
N450 M09
N460 M05
(T12 DRILL D6.8 HSS-E)
N470 T12 M06
N480 D12
N490 S2800 M03
N500 M08
N510 Z25
N520 Z2
N530 G01 Z-3 F600
N540 G00 Z1 (chip break)
N550 Z-2.5
N560 G01 Z-6.5
N570 G04 X0.2
N580 G00 Z2
N590 X15.858
N600 G01 Z-3
N610 G00 Z1 (chip break)
N620 Z-2.5
N630 G01 Z-6.5
N640 G04 X0.2
N650 G00 Z2
N660 Y44.142
N670 G01 Z-3
N680 G00 Z1 (chip break)
N690 Z-2.5
N700 G01 Z-6.5
N710 G04 X0.2
N720 G00 Z2
N730 X44.142
N740 G01 Z-3
N750 G00 Z1 (chip break)
N760 Z-2.5
N770 G01 Z-6.5
N780 G04 X0.2
N790 G00 Z2
N800 Z25
N810 G54
N820 G00 X10 Y30
N830 Z2
N840 G01 Z-3 F600
N850 G00 Z1 (chip break)
N860 Z-2.5
N870 G01 Z-6.5
N880 G04 X0.2
N890 G00 Z2
N900 X50
N910 G01 Z-3
N920 G00 Z1 (chip break)
N930 Z-2.5
N940 G01 Z-6.5
N950 G04 X0.2
N960 G00 Z2
N970 Y10
N980 G01 Z-3
N990 G00 Z1 (chip break)
N1000 Z-2.5
N1010 G01 Z-6.5
N1020 G04 X0.2
N1030 G00 Z2
N1040 X10
N1050 G01 Z-3
N1060 G00 Z1 (chip break)
N1070 Z-2.5
N1080 G01 Z-6.5
N1090 G04 X0.2
N1100 G00 Z2
N1110 Z50
N1120 M09
N1130 M05
(machine coordinates: G53 suppresses the zero offset)
N1140 G53 G00 Z0
N1150 G00 X10 Y10
N1160 M30
