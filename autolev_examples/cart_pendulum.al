% cart_pendulum.al -- a cart on a horizontal track carrying a pendulum.  Only
% second derivatives are declared (MOTIONVARIABLES' X'', TH''): X' and TH' act
% as the generalized speeds, as in Autolev's q''-only models.

NEWTONIAN N
FRAMES    A                    % the pendulum rod
PARTICLES CART, BOB
MOTIONVARIABLES' X'', TH''
CONSTANTS MC, MB, L, G

MASS CART = MC, BOB = MB
SIMPROT(N, A, 3, TH)
P_NO_CART> = X*N1>
P_CART_BOB> = -L*A2>
V_CART_N> = X'*N1>
A_CART_N> = X''*N1>
V2PTS(N, A, CART, BOB)
A2PTS(N, A, CART, BOB)

GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()

INPUT MC = 2, MB = 0.5, L = 0.8, G = 9.81
INPUT X = 0, TH = 30 deg, X' = 0, TH' = 0
INPUT TFINAL = 5, INTEGSTP = 0.01
OUTPUT T, X, TH deg
CODE DYNAMICS() cart_pendulum.c
