; expect: 3:16: feed move with F0: a zero feed rate never reaches the end point
G43.4 H1
G93 G2 X10. Y0 F0 R5. Z0 A0 C0
