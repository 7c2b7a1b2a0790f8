; expect: 4:4: X10 without a decimal point: least input increments or whole units as the control is set (on a control in decimal point input I, X10 is 0.010 mm); write X10.
G43.4 H1
G1 X0 Y0 Z50. A10. C0 F100
G1 X10 Y20. (hand-edited)
