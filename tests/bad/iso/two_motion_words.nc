; expect: 3:4: two motion words in one block
G43.4 H1
G0 G1 X0 Y0 Z0 A10. C0 F100
