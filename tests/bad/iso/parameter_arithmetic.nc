; expect: 5:9: division by zero
%
O2001
#1 = 1200.
#2 = #1 / [#1 - 1200.] (PLUNGE FEED)
G21 G17 G90 G54
G43.4 H1
G1 X10. Y0. Z5. A0. C0. F#2
M30
%
