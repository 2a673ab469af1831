G21         ; Set units to mm
G90         ; Absolute positioning
G1 Z5 F1500      ; Move to clearance level

;
; Operation:    0
; Name:         
; Type:         Engrave
; Paths:        2
; Direction:    Conventional
; Cut Depth:    3.175
; Pass Depth:   3.175
; Plunge rate:  127
; Cut rate:     100
;

; Path 0
; Rapid to initial position
G1 X129.1062 Y-33.3832 F1500
G1 Z0.0000
; plunge
G1 Z-3.1750 F127
; cut
G1 X129.0943 Y-33.3862 F100
G1 X129.0851 Y-33.3949
G1 X129.0783 Y-33.4091
G1 X129.0742 Y-33.4286
G1 X129.0729 Y-33.4540
G1 X129.0745 Y-33.4850
G1 X129.0785 Y-33.5219
G1 X129.0856 Y-33.5645
G1 X129.0953 Y-33.6133
G1 X129.1080 Y-33.6679
G1 X129.1237 Y-33.7286
G1 X129.1423 Y-33.7952
G1 X129.1641 Y-33.8683
G1 X129.1903 Y-33.9534
G1 X129.2162 Y-34.0405
G1 X129.2413 Y-34.1292
G1 X129.2665 Y-34.2199
