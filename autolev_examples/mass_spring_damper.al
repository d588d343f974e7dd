% mass_spring_damper.al -- a cart on a vertical spring and damper, pushed by a
% prescribed force F(t).  X is measured down from the spring's unstretched end.

NEWTONIAN N
PARTICLES C                    % the cart
MOTIONVARIABLES' X', V'
CONSTANTS M, K, B, G, F0, OMEGA
SPECIFIED F                    % a force prescribed as a function of time

MASS C = M
X' = V
P_NO_C> = X*N1>
V_C_N> = V*N1>

F = F0*SIN(OMEGA*T)
GRAVITY(G*N1>)
FORCE(C, (-K*X - B*V + F)*N1>)

ZERO = FR() + FRSTAR()
KANE()

INPUT M = 2 kg, K = 80 N/m, B = 1.5 N*sec/m, G = 9.81 m/sec^2
INPUT F0 = 3 N, OMEGA = 5 rad/sec
INPUT X = 0.1 m, V = 0 m/sec
INPUT TFINAL = 4, INTEGSTP = 0.02
OUTPUT T sec, X m, V m/sec
CODE DYNAMICS() mass_spring_damper.c
