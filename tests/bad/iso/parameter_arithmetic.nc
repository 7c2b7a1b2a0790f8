; expect: 5:6: parameter #2 is assigned an expression: only a number is read (arithmetic is not supported)
%
O2001
#1 = 1200.
#2 = #1 * 0.5 (PLUNGE FEED)
G21 G17 G90 G54
G43.4 H1
G1 X10. Y0. Z5. A0. C0. F#2
M30
%
