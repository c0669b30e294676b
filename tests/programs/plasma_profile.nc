%plasma_profile
; --------------------------------------------------------------------------
; plasma_profile.nc
;
; What:    plasma cut of a flange with an R30 saddle and two holes: no Z words
;          at all, torch on/off H1/H2, THC on/off H10/H11, extraction M08/M09,
;          pierce dwell G04 X0.3 alone in its block, arc lead-ins, kerf
;          already in the path (no radius compensation), holes G03 then the
;          outside G02.
; Style:   SheetCam-like plasma post: zero-padded N0010 step 10, 3 decimals.
; Origin:  written for this project in the style of SheetCam output, 2026
; Machine: config/xyz_machine.yaml: axes X Y Z, no rotary (runs unchanged on
;          config/xyzc_machine.yaml, C not programmed)
; Offsets: zero offsets of the machine file (zero_offsets): G54 = X100 Y50
;          Z-20, G55 = X300 Y50 Z-20 (machine = program + offset)
; Time:    ~12.6 s of motion (11.1 s feed over 470 mm, 1.5 s rapid) + 0.9 s
;          dwell, estimated as path length / feed
; --------------------------------------------------------------------------
(Filename: plasma_profile.tap)
(Post processor: TwinCAT plasma THC - H1/H2 torch, H10/H11 THC, M08/M09 extraction)
(Material: mild steel 3 mm - 45 A - kerf 1.6 - cut F2800)
(Part: FLANGE_100x80 with R30 saddle, 2 holes D16)
N0010 G71
N0020 G90 G94 G40 G17
N0030 G54
N0040 M08
(Process: plasma inside offset - hole at X25 Y40)
N0050 G00 X28.7 Y36.5
N0060 H1
N0070 G04 X0.3
N0080 H10
N0090 G03 X32.2 Y40 I0 J3.5 F1600
N0100 X32.2 Y40 I-7.2 J0 F2000
N0110 X31.766 Y42.463 I-7.2 J0 (overburn)
N0120 H11
N0130 H2
(Process: plasma inside offset - hole at X75 Y40)
N0140 G00 X78.7 Y36.5
N0150 H1
N0160 G04 X0.3
N0170 H10
N0180 G03 X82.2 Y40 I0 J3.5 F1600
N0190 X82.2 Y40 I-7.2 J0 F2000
N0200 X81.766 Y42.463 I-7.2 J0 (overburn)
N0210 H11
N0220 H2
(Process: plasma outside offset - profile)
N0230 G00 X-5.8 Y35
N0240 H1
N0250 G04 X0.3
N0260 H10
N0270 G03 X-0.8 Y40 I0 J5
N0280 G01 Y72 F2800
N0290 G02 X8 Y80.8 I8.8 J0
N0300 G01 X30
N0310 G02 X30.533 Y80.596 I0 J-0.8
N0320 G03 X69.467 Y80.596 I19.467 J21.765
N0330 G02 X70 Y80.8 I0.533 J-0.596
N0340 G01 X92
N0350 G02 X100.8 Y72 I0 J-8.8
N0360 G01 Y8
N0370 G02 X92 Y-0.8 I-8.8 J0
N0380 G01 X8
N0390 G02 X-0.8 Y8 I0 J8.8
N0400 G01 Y41 (overburn)
N0410 H11
N0420 H2
N0430 M09
N0440 G00 X0 Y150
N0450 M30
