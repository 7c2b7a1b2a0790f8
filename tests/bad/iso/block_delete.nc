; expect: 3:1: block delete (/) is not supported
G43.4 H1
/G1 X0 Y0 Z0 A10. C0 F100
