; expect: 4:1: arc needs I, J, K or R
G43.4 H1
G1 X0 Y0 Z0 A10. C0 F100
G2 X10. Y0
