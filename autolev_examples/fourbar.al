% fourbar.al -- four uniform links, link 1 being the ground N.  Joint angles Q1,
% Q2, Q3 (each link relative to the one before, about N3>); the loop closes where
% the free end of link 4 meets the start of link 1, so Q2 and Q3 follow Q1.
% Two auxiliary speeds give the closing point extra velocity, revealing the
% force (F1, F2) the closing joint carries.  N2> is up.

NEWTONIAN N                    % link 1, from NO to P2
BODIES    B2, B3, B4           % links 2, 3, 4
POINTS    P2, P3, P4, P5, PA   % the joints, the free end, the auxiliary point
MOTIONVARIABLES' Q{3}', U{3}', UA{2}'
VARIABLES F1, F2
CONSTANTS L1, L2, L3, L4, RHO, G

MASS B2 = RHO*L2, B3 = RHO*L3, B4 = RHO*L4
INERTIA B2, 0, 0, RHO*L2^3/12
INERTIA B3, 0, 0, RHO*L3^3/12
INERTIA B4, 0, 0, RHO*L4^3/12

SIMPROT(N, B2, 3, Q1)
SIMPROT(B2, B3, 3, Q2)
SIMPROT(B3, B4, 3, Q3)
Q1' = U1
Q2' = U2
Q3' = U3
W_B2_N> = U1*N3>
W_B3_B2> = U2*N3>
W_B4_B3> = U3*N3>

P_NO_P2> = L1*N1>
P_P2_B2O> = L2/2*B21>
P_P2_P3> = L2*B21>
P_P3_B3O> = L3/2*B31>
P_P3_P4> = L3*B31>
P_P4_B4O> = L4/2*B41>
P_P4_P5> = L4*B41>

V_P2_N> = 0>
V2PTS(N, B2, P2, B2O)
V2PTS(N, B2, P2, P3)
V2PTS(N, B3, P3, B3O)
V2PTS(N, B3, P3, P4)
V2PTS(N, B4, P4, B4O)
V2PTS(N, B4, P4, P5)

% the free end of link 4 stays at NO; the auxiliary speeds let it move
DEPENDENT[1] = DOT(V_P5_N>, N1>) + UA1
DEPENDENT[2] = DOT(V_P5_N>, N2>) + UA2
CONSTRAIN(DEPENDENT[U2, U3])
V_PA_N> = UA1*N1> + UA2*N2>
AUXILIARY[1] = UA1
AUXILIARY[2] = UA2
CONSTRAIN(AUXILIARY[UA1, UA2])

GRAVITY(-G*N2>)
FORCE_PA> = F1*N1> + F2*N2>
ZERO = FR() + FRSTAR()
KANE(F1, F2)

INPUT L1 = 2 m, L2 = 1 m, L3 = 2 m, L4 = 1 m, RHO = 5 kg/m, G = 9.81 m/sec^2
INPUT Q1 = 90 deg, Q2 = 90 deg, Q3 = 90 deg, U1 = 0.5 rad/sec
INPUT TFINAL = 2, INTEGSTP = 0.01
OUTPUT T sec, Q1 deg, Q2 deg, Q3 deg, F1 N, F2 N
CODE DYNAMICS() fourbar.c
