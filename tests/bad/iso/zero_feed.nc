; expect: 3:21: feed move with F0: a zero feed rate never reaches the end point
G43.4 H1
G1 X0 Y0 Z0 A10. C0 F0
