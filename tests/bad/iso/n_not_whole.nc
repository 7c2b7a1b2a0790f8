; expect: 3:1: block number must be a whole number
G43.4 H1
N1.5 G1 X0 Y0 Z0 A10. C0 F100
