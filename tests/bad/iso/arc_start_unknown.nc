; expect: 3:12: arc centre needs a known start point
G43.4 H1
G2 X10. Y0 I5. J0 F100
