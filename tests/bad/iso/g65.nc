; expect: 2:1: call of O9010: no such label in this file
G65 P9010 A1. B2.
M30
