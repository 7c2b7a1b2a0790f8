; expect: 3:4: word 'X' has no value
G43.4 H1
G1 X Y0 Z0 A10. C0 F100
