; expect: 3:4: expressions and parameters in axis words are not supported
G43.4 H1
G1 X[1+2] Y0 Z0 A10. C0 F100
