; expect: 4:1: feed move at a zero feed rate (F0 or FEDRAT/0 in effect): it never reaches the end point
G43.4 H1
G0 X0 Y0 Z0 A10. C0 F0
G1 X1.
