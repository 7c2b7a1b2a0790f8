; expect: 3:25: the spindle speed 0.0101 cannot be written with 3 decimals, the most the controller reads (it would read as another value)
G43.4 H1
G1 X0 Y0 Z0 A10 C0 F100 S.0101 M3
