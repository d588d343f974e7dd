% nlink_pendulum.al -- four uniform rods linked by pins in a vertical plane,
% the first pinned at NO.  Joint angles are relative (Q2 is the angle of link B
% from link A), the speeds are their rates.  N1> points down.

NEWTONIAN N
BODIES    A, B, C, D
POINTS    P{3}                 % the joints between the links
MOTIONVARIABLES' Q{4}', U{4}'
CONSTANTS L, M, G

MASS A = M, B = M, C = M, D = M
INERTIA A, 0, 0, M*L^2/12
INERTIA B, 0, 0, M*L^2/12
INERTIA C, 0, 0, M*L^2/12
INERTIA D, 0, 0, M*L^2/12

SIMPROT(N, A, 3, Q1)
SIMPROT(A, B, 3, Q2)
SIMPROT(B, C, 3, Q3)
SIMPROT(C, D, 3, Q4)

Q1' = U1
Q2' = U2
Q3' = U3
Q4' = U4
W_A_N> = U1*N3>
W_B_A> = U2*N3>
W_C_B> = U3*N3>
W_D_C> = U4*N3>

P_NO_AO> = L/2*A1>
P_NO_P1> = L*A1>
P_P1_BO> = L/2*B1>
P_P1_P2> = L*B1>
P_P2_CO> = L/2*C1>
P_P2_P3> = L*C1>
P_P3_DO> = L/2*D1>

V2PTS(N, A, NO, AO)
V2PTS(N, A, NO, P1)
V2PTS(N, B, P1, BO)
V2PTS(N, B, P1, P2)
V2PTS(N, C, P2, CO)
V2PTS(N, C, P2, P3)
V2PTS(N, D, P3, DO)

GRAVITY(G*N1>)
ZERO = FR() + FRSTAR()
KANE()

INPUT L = 0.5 m, M = 1 kg, G = 9.81 m/sec^2
INPUT Q1 = 20 deg, Q2 = 10 deg, Q3 = -10 deg, Q4 = 5 deg
INPUT U1 = 0, U2 = 0, U3 = 0, U4 = 0
INPUT TFINAL = 3, INTEGSTP = 0.01
OUTPUT T sec, Q1 deg, Q2 deg, Q3 deg, Q4 deg
CODE DYNAMICS() nlink_pendulum.c
