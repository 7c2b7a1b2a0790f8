; expect: 3:13: tool-axis vector needs I, J and K
G43.5 H1
G1 X0 Y0 Z0 I0 J0 F100
