% encoded.al -- CODE ALGEBRAIC() with ENCODE: a rotation matrix and its derivative.
NEWTONIAN N
FRAMES A
VARIABLES Q
SIMPROT(N, A, 3, Q)
R = N_A
DR = D(R, Q)
ENCODE R, DR
INPUT Q = 30 DEG
CODE ALGEBRAIC() encoded.c
