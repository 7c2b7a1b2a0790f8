; expect: 3:7: word 'X' appears twice
G43.4 H1
G1 X0 X1. Y0 Z0 A10. C0 F100
