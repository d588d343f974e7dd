"""Small models more than one test file reads."""

# a pendulum driven by a torque TQ, whose linearization is worked out by hand
PENDULUM = """NEWTONIAN N
BODIES A
MOTIONVARIABLES' Q', U'
CONSTANTS G, L, M
SPECIFIED TQ
SIMPROT(N, A, 3, Q)
Q' = U
W_A_N> = U*A3>
P_NO_AO> = L*A1>
V_AO_N> = DT(P_NO_AO>, N)
MASS A = M
INERTIA A, 0, 0, 0
GRAVITY(G*N1>)
TORQUE(A, TQ*A3>)
ZERO = FR() + FRSTAR()
KANE()
X = L*COS(Q)
OUTPUT Q, X, U'
INPUT G = 9.81, L = 2, M = 3, Q = 10 deg, U = 0, TFINAL = 1
CODE DYNAMICS() pendulum.c
"""
