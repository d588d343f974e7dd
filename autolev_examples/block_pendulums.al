% block_pendulums.al -- a block sliding along the floor away from a wall, carrying
% a compound pendulum B that carries a simple pendulum (bob C on a massless rod).
% The block is held by a spring and damper to the wall and pushed by a force
% F(t); a torque TQ(t) acts on B from the wall; a torsional spring acts between
% the rod of C and B.  N2> is up.

NEWTONIAN N                    % the wall and floor
PARTICLES A, C                 % the block; the simple pendulum's bob
BODIES    B                    % the compound pendulum
FRAMES    CF                   % the simple pendulum's rod
POINTS    PBC                  % the pin between B and the rod
MOTIONVARIABLES' Q{3}', U{3}'
CONSTANTS MA, MB, MC, IBZZ, L, G, K, CDAMP, KT
SPECIFIED F, TQ

MASS A = MA, B = MB, C = MC
INERTIA B, 0, 0, IBZZ

SIMPROT(N, B, 3, Q2)           % Q2: B from the vertical
SIMPROT(B, CF, 3, Q3)          % Q3: the rod relative to B
Q1' = U1
Q2' = U2
Q3' = U3
W_B_N> = U2*N3>
W_CF_B> = U3*N3>

P_NO_A> = Q1*N1>
V_A_N> = U1*N1>
P_A_BO> = -2*L/3*B2>
P_BO_PBC> = -L/3*B2>
P_PBC_C> = -L*CF2>
V2PTS(N, B, A, BO)
V2PTS(N, B, A, PBC)
V2PTS(N, CF, PBC, C)

GRAVITY(-G*N2>)
FORCE(NO/A, (-K*Q1 - CDAMP*U1)*N1>)
FORCE(A, F*N1>)
TORQUE(N/B, TQ*N3>)
TORQUE(B/CF, -KT*Q3*N3>)

ZERO = FR() + FRSTAR()
KANE()

INPUT MA = 2, MB = 1, MC = 0.5, IBZZ = 0.1, L = 1, G = 9.81, K = 20, CDAMP = 0.5
INPUT KT = 2
INPUT Q1 = 0.1, Q2 = 20 deg, Q3 = -10 deg, U1 = 0, U2 = 0, U3 = 0
INPUT TFINAL = 5, INTEGSTP = 0.01
OUTPUT T, Q1, Q2 deg, Q3 deg
CODE DYNAMICS() block_pendulums.c
