% LEGACY_CART.AL -- a rod hanging from a cart on a horizontal track (written for the
% autolev documentation in the style of 1990s models: no INPUT values; Autolev's
% program read them from LEGACY_CART.IN)
NEWTONIAN N
PARTICLES C
BODIES R
MOTIONVARIABLES' X', Q', V', W'
CONSTANTS MC, MR, L, G, K       % masses, rod length, gravity, spring stiffness
SIMPROT(N, R, 3, Q)
X' = V
Q' = W
P_NO_C> = X*N2>
P_C_RO> = L/2*R1>
V_C_N> = V*N2>
W_R_N> = W*N3>
V2PTS(N, R, C, RO)
MASS C = MC, R = MR
INERTIA R, 0, MR*L^2/12, MR*L^2/12, 0, 0, 0
GRAVITY(G*N1>)                  % N1> points down
FORCE_C> = -K*X*N2>             % a spring holds the cart
ZERO = FR() + FRSTAR()
KANE()
OUTPUT T, X, Q, V, W
CODE DYNAMICS() legacy_cart.c
