; expect: 3:4: malformed number '1.2.3'
G43.4 H1
G1 X1.2.3 Y0 Z0 A10. C0 F100
