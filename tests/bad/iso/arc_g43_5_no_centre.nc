; expect: 4:1: arc needs I, J, K or R (in a G43.5 block I, J, K are the tool axis)
G43.4 H1
G1 X0 Y0 Z0 A10. C0 F100
G3z8.G43.5
