%contour_2d_arcs
; --------------------------------------------------------------------------
; contour_2d_arcs.nc
;
; What:    2D outside profile of a 60 x 40 plate: lines and tangent arcs
;          G02/G03 with I J (corner R13 tool path, an R12 notch), lead-in and
;          lead-out arcs R5, two depth passes; T1 M06 D1, S M03, coolant
;          M08/M09.
; Style:   Fusion 360-like post: N numbers step 5, 3 decimals with trailing
;          zeros dropped, modal words suppressed, arcs with both I and J.
; Origin:  written for this project in the style of Fusion 360 output, 2026
; Machine: config/xyz_machine.yaml: axes X Y Z, no rotary (runs unchanged on
;          config/xyzc_machine.yaml, C not programmed)
; Offsets: zero offsets of the machine file (zero_offsets): G54 = X100 Y50
;          Z-20, G55 = X300 Y50 Z-20 (machine = program + offset)
; Time:    ~16.2 s of motion (14.7 s feed over 532 mm, 1.5 s rapid) + 0.0 s
;          dwell, estimated as path length / feed
; --------------------------------------------------------------------------
(T1  D=10 CR=0 - ZMIN=-5 - FLAT END MILL)
N10 G90 G94 G17
N15 G71
(2D CONTOUR1)
N20 T1 M06
N25 D1
N30 S12000 M03
N35 G54
N40 M08
N45 G00 X-10 Y10
N50 Z15
N55 Z5
N60 G01 Z1 F1000
N65 Z-2.5 F300
N70 Y15 F2500
N75 G03 X-5 Y20 I0 J5
N80 G01 Y32
N85 G02 X8 Y45 I13 J0
N90 G01 X18
N95 G02 X23 Y40 I0 J-5
N100 G03 X37 Y40 I7 J0
N105 G02 X42 Y45 I5 J0
N110 G01 X52
N115 G02 X65 Y32 I0 J-13
N120 G01 Y8
N125 G02 X52 Y-5 I-13 J0
N130 G01 X8
N135 G02 X-5 Y8 I0 J13
N140 G01 Y20
N145 G03 X-10 Y25 I-5 J0
N150 G01 Y30
N155 G00 Z5
N160 Y10
N165 G01 Z1 F1000
N170 Z-5 F300
N175 Y15 F2500
N180 G03 X-5 Y20 I0 J5
N185 G01 Y32
N190 G02 X8 Y45 I13 J0
N195 G01 X18
N200 G02 X23 Y40 I0 J-5
N205 G03 X37 Y40 I7 J0
N210 G02 X42 Y45 I5 J0
N215 G01 X52
N220 G02 X65 Y32 I0 J-13
N225 G01 Y8
N230 G02 X52 Y-5 I-13 J0
N235 G01 X8
N240 G02 X-5 Y8 I0 J13
N245 G01 Y20
N250 G03 X-10 Y25 I-5 J0
N255 G01 Y30
N260 G00 Z15
N265 M09
N270 M05
N275 Z100
N280 X0 Y80
N285 M30
