n10 g01 x1.5 y2 (comment) ; tail
X3 Y4
G02 X5 Y4 R1
T1 M8M9
