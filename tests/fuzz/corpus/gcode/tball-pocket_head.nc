G21         ; Set units to mm
G90         ; Absolute positioning
G1 Z5 F1500      ; Move to clearance level

;
; Operation:    0
; Name:         
; Type:         Pocket
; Paths:        4
; Direction:    Conventional
; Cut Depth:    3.175
; Pass Depth:   3.175
; Plunge rate:  127
; Cut rate:     100
;

; Path 0
; Rapid to initial position
G1 X79.4614 Y-52.3628 F1500
G1 Z0.0000
; plunge
G1 Z-3.1750 F127
; cut
G1 X79.3748 Y-52.4797 F100
G1 X79.3542 Y-52.5066
G1 X79.1350 Y-52.7992
G1 X79.1218 Y-52.8162
G1 X79.0680 Y-52.8866
G1 X79.0606 Y-52.8967
G1 X78.9161 Y-53.0854
G1 X78.9097 Y-53.0933
G1 X78.8782 Y-53.1340
G1 X78.7535 Y-53.2955
G1 X78.7444 Y-53.3074
G1 X78.7385 Y-53.2897
G1 X78.5310 Y-52.7174
G1 X78.5038 Y-52.6468
G1 X78.6669 Y-52.5833
G1 X78.6669 Y-52.5835
G1 X78.7037 Y-52.5696
