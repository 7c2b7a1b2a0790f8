; expect: 3:13: tool-axis vector shorter than 0.001 is not a direction
G43.5 H1
G1 X0 Y0 Z0 I0 J0 K0.0000001 F100
