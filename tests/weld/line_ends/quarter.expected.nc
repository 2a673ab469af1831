%
(kerf weld line ends: a quarter circle of 19 points, comments and a blank line)
G21 G90 G17
G0 X10 Y0
M3
G3 X0 Y10 I-10.0115 J-0.0115 F600
(start)
(half way)

M5
G0 X0 Y0
%
