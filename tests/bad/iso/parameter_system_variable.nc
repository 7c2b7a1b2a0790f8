; expect: 5:1: parameter #5221 is a system variable (#1000 and up: the control's offsets, positions and signals), not a value of this program
%
O2003
G21 G17 G90
#5221 = -250. (G54 X)
G54
M30
%
