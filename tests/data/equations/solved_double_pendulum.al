% A double pendulum of point masses whose equations are formed by SOLVE, not KANE():
% the speeds' derivatives are defined as SOLVE's solution.  A torque on the first
% link is given as a function of T.  Written for the autolev tests.
NEWTONIAN N
FRAMES A, B
PARTICLES P1, P2
MOTIONVARIABLES' Q{2}', U{2}'
CONSTANTS L1, L2, M1, M2, G
SPECIFIED TQ
MASS P1 = M1, P2 = M2
SIMPROT(N, A, 3, Q1)
SIMPROT(N, B, 3, Q2)
Q1' = U1
Q2' = U2
W_A_N> = U1*N3>
W_B_N> = U2*N3>
P_NO_P1> = L1*A1>
P_P1_P2> = L2*B1>
V_P1_N> = DT(P_NO_P1>, N)
V_P2_N> = DT(P_NO_P2>, N)
A_P1_N> = DT(V_P1_N>, N)
A_P2_N> = DT(V_P2_N>, N)
TQ = 0.5*SIN(T)
GRAVITY(G*N1>)
TORQUE(N/A, TQ*N3>)
ZERO = FR() + FRSTAR()
SOLVE(ZERO, U1', U2')
INPUT L1 = 1, L2 = 0.7, M1 = 2, M2 = 1.5, G = 9.81
INPUT Q1 = 0.3, Q2 = -0.4, U1 = 0.2, U2 = 0.5, TFINAL = 1, INTEGSTP = 0.1
OUTPUT T, Q1, Q2, U1, U2
CODE DYNAMICS() solved_double_pendulum.c
