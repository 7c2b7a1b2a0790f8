; expect: 2:1: program number must be a whole number
O12.5
G43.4 H1
G1 X0 Y0 Z0 A10. C0 F100
