; expect: 4:12: arc has both I J K and R
G43.4 H1
G1 X0 Y0 Z0 A10. C0 F100
G2 X10. Y0 I5. J0 R5.
