; expect: 3:26: spindle speed S8000.5 is not a whole number: an ISO/Fanuc control reads S as whole revolutions per minute (S takes no decimal point)
G43.4 H1
G1 X0 Y0 Z0 A10. C0 F100 S8000.5 M3
