; expect: 2:1: G4 needs X (seconds, with a decimal point) or P (milliseconds)
G4
