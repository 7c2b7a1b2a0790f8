; expect: 5:1: setting parameter #5221 is not supported: only #1-#33, #100-#199 and #500-#999 hold the program's own values (the others are the control's)
%
O2003
G21 G17 G90
#5221 = -250. (G54 X)
G54
M30
%
