; expect: 4:16: word 'K' is not in the arc plane
G43.4 H1
G1 X0 Y0 Z0 A10. C0 F100
G2 X10. Y0 I5. K1.
