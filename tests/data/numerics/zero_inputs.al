% zero_inputs.al -- a pendulum whose length has no INPUT: its acceleration is 0/0.
NEWTONIAN N
FRAMES A
PARTICLES P
MOTIONVARIABLES' THETA''
CONSTANTS L, G, M
MASS P = M
SIMPROT(N, A, 3, THETA)
P_NO_P> = L*A1>
V2PTS(N, A, NO, P)
GRAVITY(G*N1>)
ZERO = FR() + FRSTAR()
KANE()
INPUT G = 9.81, M = 1, THETA = 0.1
OUTPUT T, THETA
CODE DYNAMICS() zero_inputs.c
