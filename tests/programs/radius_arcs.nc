%radius_arcs
; --------------------------------------------------------------------------
; radius_arcs.nc
;
; What:    lever profile programmed with R arcs: a rounded-triangle cut-out
;          (G03 R3 corners, R2.5 leads) and the outer profile of two bosses
;          joined by tangents: G02 R-22 round boss 1 (196 deg, > 180 deg), G02
;          R12 round boss 2, G03 R5 leads; two depth passes.
; Style:   SolidCAM-like post: N1 step 1, fixed 3 decimals (X38.440), contour
;          section comments.
; Origin:  written for this project in the style of SolidCAM output, 2026
; Machine: config/xyz_machine.yaml: axes X Y Z, no rotary (runs unchanged on
;          config/xyzc_machine.yaml, C not programmed)
; Offsets: zero offsets of the machine file (zero_offsets): G54 = X100 Y50
;          Z-20, G55 = X300 Y50 Z-20 (machine = program + offset)
; Time:    ~19.4 s of motion (17.7 s feed over 632 mm, 1.7 s rapid) + 0.0 s
;          dwell, estimated as path length / feed
; --------------------------------------------------------------------------
(SOLIDCAM - LEVER_PLATE.PRZ)
(TOOL 3 - EM D8.000 - FLUTES 3 - H3 D3)
N1 G71 G90 G17 G40 G94
N2 G54
N3 T3 M06
N4 D3
N5 S8000 M03
N6 M08
(-----CONTOUR - F_TRI_CUTOUT-----)
N7 G00 X40.000 Y60.000 (PRE-DRILLED D10)
N8 Z25.000
N9 Z2.000
N10 G01 Z-6.000 F300
N11 X38.219 Y63.915 F1200
N12 G03 X34.804 Y63.000 R2.500
N13 G01 X32.206 Y58.500
N14 G03 X34.804 Y54.000 R3.000
N15 G01 X45.196
N16 G03 X47.794 Y58.500 R3.000
N17 G01 X42.598 Y67.500
N18 G03 X37.402 Y67.500 R3.000
N19 G01 X34.804 Y63.000
N20 G03 X35.719 Y59.585 R2.500
N21 G01 X40.000 Y60.000
N22 G00 Z2.000
(-----CONTOUR - F_OUTER_PROFILE-----)
N23 X89.328 Y42.930
N24 Z1.000
N25 G01 Z-3.000 F600
N26 X87.264 Y48.563 F2800
N27 G03 X80.849 Y51.538 R5.000
N28 G01 X47.569 Y39.343
N29 G02 X38.440 Y81.945 R-22.000
N30 G01 X109.149 Y86.970
N31 G02 X114.129 Y63.733 R12.000
N32 G01 X80.849 Y51.538
N33 G03 X77.875 Y45.123 R5.000
N34 G00 Z2.000
N35 X89.328 Y42.930
N36 Z1.000
N37 G01 Z-6.000 F600
N38 X87.264 Y48.563 F2800
N39 G03 X80.849 Y51.538 R5.000
N40 G01 X47.569 Y39.343
N41 G02 X38.440 Y81.945 R-22.000
N42 G01 X109.149 Y86.970
N43 G02 X114.129 Y63.733 R12.000
N44 G01 X80.849 Y51.538
N45 G03 X77.875 Y45.123 R5.000
N46 G00 Z25.000
N47 M09
N48 M05
N49 X0.000 Y150.000
N50 M30
