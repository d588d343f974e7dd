% all_constructs.al -- one of every syntactic form the grammar knows.
% Not a meaningful model: a parser test and a fuzzing seed.
AUTOZ ON
AUTORHS OFF
DEGREES OFF
OVERWRITE ALL
BEEPSOUND OFF
PAUSE 0
DIGITS 7
autoepsilon 1.0E-7
COMPLEX OFF
NEWTONIAN N
FRAMES A, B
BODIES C, D
PARTICLES P, Q
POINTS O, E{2}
CONSTANTS L{2}, M+, K-, G = 9.81, R{1:2,1:2}, S{2,2}, WO{2}RD{1:2}
VARIABLES X', Y'', W{3}'
MOTIONVARIABLES' Q{2}', U{2}'
SPECIFIED F, TAU'
IMAGINARY J
MASS C = MC, D = MD = 2, P = M, Q = M
INERTIA C, IC1, IC2, IC3
INERTIA D(A), ID = MD*L1^2/12, 0, ID, 0, 0, 0
SIMPROT(N, A, 3, Q1)
SIMPROT(A, B, -2, Q2);
DIRCOS(A, C, BODY123, W1, W2, W3)
KINDIFFS(A, C, BODY123, W1, W2, W3)
ANGVEL(N, C)
Q1' = U1
Q2' = U2
W_A_N> = U1*N3>
ALF_A_N> := DT(W_A_N>, N)
P_NO_O> = L1*A1> + L2*A2>
P_O_P> = X*B1> - Y*B2> + 0>
V_O_N> = DT(P_NO_O>, N)
V2PTS(N, A, NO, O)
V1PT(N, B, O, P)
A2PTS(N, A, NO, O)
I_C_CO>> = 1>>
D1>> = N1>*N2>
GRAVITY(G*N1>)
GRAVITY(-G*N2>, C, D)
FORCE(O/P, -K*P_O_P>)
FORCE_Q> += F*N1>
TORQUE(A/B, TAU*A3>)
TORQUE_C> -= 2*C3>
DEPENDENT[1] = U1 - U2
CONSTRAIN(DEPENDENT[U2])
ZERO = FR() + FRSTAR()
ZERO := -ARRANGE(ZERO, 1, G)
KANE()
E = (X + 2*Y)^2 + 3*(7 + X)*(X + Y)
E *= 2
E /= 2
E ^= 1
E -= 0
EXPAND(E, 1:2)
FACTOR(E, X)
DY = D(E, Y)
TY = TAYLOR(X*COS(Y), 0:7, X=0, Y=0)
PERTURB = TAYLOR(ZERO, 1, Q1=0:DQ1, Q1'=0:DQ1')
V = EVALUATE(TY, X=1, Y=0.5)
RPL = REPLACE(E, SIN(X)=3)
MO = [M, K; G, 0]
MO[2,2] := 1.5E+2
MB = [MO, [1, 2; 3, 4]]
COLUMN = [1; 2; &   % continued
          3]
ROOT = ROOTS([1; 2; 3; 4])
SUB = ROWS(MO, 2, 1:2)
SOLVE(PERTURB, DQ{1:2}'')
A_B = [1, 0, 0; 0, 1, 0; 0, 0, 1]
H = a^-2 - -b^2 + .5 + 1. + 1E-7 + 1.0e-08
KINETIC = KE()
UNITSYSTEM kg, meter, sec
UNITS T = S, [L1, L2] = M, HZ = KG.M^2/S
INPUT L1 = 1 m, L2 = 2 m, M = 3 kg, K = 10 N/M, Q1 = 30 deg, U1 = 0 rad/sec
INPUT TFINAL = 10, INTEGSTP = .01, ABSERR = 1.0E-08, RELERR = 1.0E-07
INPUT X' = 0 m/s, MO[1,1] = 2*SQRT(2)
OUTPUT T sec, Q1 deg, X m, KINETIC joules, DOT(V_O_N>, N1>)
ENCODE MO, E
CODE DYNAMICS() all_constructs.c, NOSUBS
CODE ALGEBRAIC(ZERO, U1'', U2'') [Q1 deg = 0, 360, 1] sweep.m
CODE NONLINEAR([E; DY], X, Y) solve.for
CODE ODE(ZERO, Q1'', Q2'') ode.c
SAVE all_constructs.all
EXIT
