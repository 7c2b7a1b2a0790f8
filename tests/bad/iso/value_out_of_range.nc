; expect: 3:4: value out of range
G43.4 H1
G1 X10000000000. Y0 Z0 A10. C0 F100
