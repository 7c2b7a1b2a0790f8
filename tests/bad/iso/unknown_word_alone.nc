; expect: 2:1: unknown word 'G29'
G29
M30
