; expect: 2:5: G4 X2: without a decimal point X is seconds or least input increments as the control is set (write X with a point, or P in milliseconds)
G04 X2
