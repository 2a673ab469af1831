G2 ; Abso; Se Type:         Engrave
; Paths:        5 G90 G17
G0 X0 Y0
M3 S1000
G1 X10 Y0 F600
G2 X20 Y0 I5 J0
G3 X10 Y0 R6
G91 G1 X-5 Y5
G4 P0.5
M5
G2
; Direction:    Convenniotal
; Cut Depth:    0.9999999999999999
; Pass Depth:   3.175
; Pl1    ÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿ    0; Set units to mm
G90         ; AbG0 X0 Y0
M3 S1000
G1 X10 Y0 F600
G2 X20 Y0 I5 J0
G3 X10 Y0 R6
G91 G1 X-5 Y5
G4 P0.5
M5
G2
; Direction:    Convenniotal
; Cut Depth:    0.999917
G0 X0 Y0
M3 S100 Y0
M3M5
G20 G0 X12 0 M3 S1000
G1 X10 Y0 F600
G2 x20 Y0 I999999999999
; Pass Depth:   3.175
; Plunge rate: %
G21  G1