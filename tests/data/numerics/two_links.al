% two_links.al -- two rods pinned end to end (masses and inertias as INPUT constants,
% for the tests of bad inertias).
NEWTONIAN N
BODIES A, B
POINTS P
MOTIONVARIABLES' Q{2}', U{2}'
CONSTANTS L, MA, MB, G, IA, IB
MASS A = MA, B = MB
INERTIA A, 0, 0, IA
INERTIA B, 0, 0, IB
SIMPROT(N, A, 3, Q1)
SIMPROT(A, B, 3, Q2)
Q1' = U1
Q2' = U2
W_A_N> = U1*N3>
W_B_A> = U2*N3>
P_NO_AO> = L/2*A1>
P_NO_P> = L*A1>
P_P_BO> = L/2*B1>
V2PTS(N, A, NO, AO)
V2PTS(N, A, NO, P)
V2PTS(N, B, P, BO)
GRAVITY(G*N1>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L = 1, MA = 1, MB = 1, G = 9.81, IA = 0.1, IB = 0.1, Q1 = 0.3, Q2 = 0.2
OUTPUT T, Q1, Q2
CODE DYNAMICS() two_links.c
