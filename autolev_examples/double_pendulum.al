% double_pendulum.al -- two point masses on rigid massless links, swinging
% in the vertical plane of the Newtonian frame N (N1> points down).
%
% Written for the autolev project as a small, complete example.

NEWTONIAN N                    % the pivot is NO, the origin of N
FRAMES    A, B                 % link 1 and link 2
PARTICLES P1, P2               % the bob at the end of each link

MOTIONVARIABLES' Q{2}', U{2}'  % joint angles and their rates
CONSTANTS L1, L2, M1, M2, G    % link lengths, masses, gravity

MASS P1 = M1, P2 = M2

% Orientation: each link turns about the horizontal axis N3>
SIMPROT(N, A, 3, Q1)
SIMPROT(N, B, 3, Q2)

% Kinematical differential equations and angular velocities
Q1' = U1
Q2' = U2
W_A_N> = U1*N3>
W_B_N> = U2*N3>

% Positions and velocities
P_NO_P1> = L1*A1>
P_P1_P2> = L2*B1>
V_NO_N>  = 0>
V2PTS(N, A, NO, P1)
V2PTS(N, B, P1, P2)

% Loads and equations of motion
GRAVITY(G*N1>)
ZERO = FR() + FRSTAR()
KANE()

% Energy, as a check on the integration
KINETIC = KE()
POTENTIAL = -M1*G*DOT(P_NO_P1>, N1>) - M2*G*DOT(P_NO_P2>, N1>)
ENERGY = KINETIC + POTENTIAL

UNITSYSTEM kg, meter, sec
INPUT M1 = 1 kg, M2 = 1 kg, L1 = 1 m, L2 = 1 m, G = 9.81 m/sec^2
INPUT Q1 = 30 deg, Q2 = 60 deg, U1 = 0 rad/sec, U2 = 0 rad/sec
INPUT TFINAL = 10, INTEGSTP = 0.01, ABSERR = 1.0E-08, RELERR = 1.0E-08

OUTPUT T sec, Q1 deg, Q2 deg, U1 rad/sec, U2 rad/sec
OUTPUT T sec, ENERGY joules

CODE DYNAMICS() double_pendulum.c
