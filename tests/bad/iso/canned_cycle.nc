; expect: 4:1: canned cycle G81 is not supported
G43.4 H1
G1 X0 Y0 Z0 A10. C0 F100
G81 X0 Y0 Z-5. R2.
