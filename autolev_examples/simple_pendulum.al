% simple_pendulum.al -- a point mass on a rigid massless rod of length L that
% swings about the Newtonian origin NO.  N1> points down, so THETA = 0 hangs.
% The only motion variable is declared with two primes: THETA' is the speed.

NEWTONIAN N
FRAMES    A                    % the rod
PARTICLES P                    % the bob
MOTIONVARIABLES' THETA''
CONSTANTS L, G, M

MASS P = M
SIMPROT(N, A, 3, THETA)        % W_A_N> = THETA'*N3> follows from this
P_NO_P> = L*A1>
V2PTS(N, A, NO, P)

GRAVITY(G*N1>)
ZERO = FR() + FRSTAR()
KANE()

INPUT L = 1 m, G = 9.81 m/sec^2, M = 1 kg
INPUT THETA = 10 deg, THETA' = 0 rad/sec
INPUT TFINAL = 5, INTEGSTP = 0.01

OUTPUT T sec, THETA deg, THETA' rad/sec
CODE DYNAMICS() simple_pendulum.c
