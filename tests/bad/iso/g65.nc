; expect: 2:1: G65: a macro call is not supported (the motion it makes would be lost)
G65 P9010 A1. B2.
M30
