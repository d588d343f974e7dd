% a pendulum swung up by a torque at its pivot: the classic direct-collocation example
NEWTONIAN N
BODIES A
MOTIONVARIABLES' Q', U'
CONSTANTS M, L, G
SPECIFIED T
SIMPROT(N, A, 3, Q)
Q' = U
W_A_N> = U*A3>
P_NO_AO> = L*A1>
V_AO_N> = DT(P_NO_AO>, N)
MASS A = M
INERTIA A, 0, 0, 0
GRAVITY(G*N1>)
TORQUE(A, T*A3>)
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 1 KG, L = 1 M, G = 9.81 M/S^2, Q = 0 RAD, U = 0 RAD/S, TFINAL = 2 S
CODE DYNAMICS() swingup.c
