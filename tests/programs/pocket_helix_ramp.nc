%pocket_helix_ramp
; --------------------------------------------------------------------------
; pocket_helix_ramp.nc
;
; What:    circular pocket D33.5, 4 deep: helical ramp R4 entered above the
;          stock, three full-turn G03 helix blocks (I only, Z changing, pitch
;          1.5), a flat turn, spiral-out half circles with alternating centres
;          and a finishing full circle.
; Style:   Mastercam-like post: N100 step 2, leading-dot numbers (Z.5), zero
;          centre words omitted, tool offset as D.
; Origin:  written for this project in the style of Mastercam output, 2026
; Machine: config/xyz_machine.yaml: axes X Y Z, no rotary (runs unchanged on
;          config/xyzc_machine.yaml, C not programmed)
; Offsets: zero offsets of the machine file (zero_offsets): G54 = X100 Y50
;          Z-20, G55 = X300 Y50 Z-20 (machine = program + offset)
; Time:    ~16.9 s of motion (15.6 s feed over 328 mm, 1.3 s rapid) + 0.0 s
;          dwell, estimated as path length / feed
; --------------------------------------------------------------------------
(PROGRAM NAME - POCKET_HELIX_RAMP)
(DATE=DD-MM-YY - 12-03-26 TIME=HH:MM - 09:41)
(MCAM FILE - BRACKET_BORE)
(NC FILE - POCKET_HELIX_RAMP.NC)
(MATERIAL - ALUMINUM MM - 6061)
( T2 |  8MM FLAT ENDMILL | H2 | D2 )
N100 G71 G00 G17 G40 G90 G94
N102 T2 M06
N104 G90 G54 G00 X56.5 Y37.25 S9500 M03
N106 D2 Z25 M08
N108 Z3
N110 G01 Z.5 F250
N112 G03 X56.5 Y37.25 Z-1 I-4 F900
N114 X56.5 Y37.25 Z-2.5 I-4
N116 X56.5 Y37.25 Z-4 I-4
N118 X56.5 Y37.25 I-4 F1500
N120 X46.75 Y37.25 I-4.875
N122 X60 Y37.25 I6.625
N124 X43.25 Y37.25 I-8.375
N126 X63.5 Y37.25 I10.125
N128 X39.75 Y37.25 I-11.875
N130 X39.75 Y37.25 I12.75 (FINISH WALL)
N132 G01 X52.5
N134 G00 Z25
N136 M09
N138 M05
N140 X0 Y100
N142 M30
