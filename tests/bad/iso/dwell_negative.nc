; expect: 2:4: G4 X-1.5: a dwell time cannot be negative
G4 X-1.5
