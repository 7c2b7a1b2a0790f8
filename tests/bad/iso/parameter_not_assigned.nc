; expect: 6:18: parameter #101 is read before it is assigned: its value is the machine's
%
O2002
G21 G17 G90 G54
G43.4 H1
G1 X10. Y0. Z5. F#101
M30
%
