% spring_chain.al -- five equal masses in a horizontal line (no gravity), X1..X5
% their displacements along N1> from the unstretched rest position.  The first mass
% is tied to the wall (NO) by a soft spring KS and a damper C; neighbours are joined
% by springs of stiffness K and dampers C.  The last mass is driven by
% F0*(1 - COS(OMEGA*T)), a force that starts with zero value and rate, so the fast
% modes are hardly excited.  With K large the chain is nearly rigid: the slow motion
% (the block on the soft spring, period ~3 s, and the drive) is smooth while the
% fast modes (frequencies up to about 2*SQRT(K/M), lightly damped) make the
% equations stiff for an explicit integrator.
% Written for bench/work_precision.py (run it with K = 1e2 ... 1e8).

NEWTONIAN N
PARTICLES P1, P2, P3, P4, P5
MOTIONVARIABLES' X{5}', V{5}'
CONSTANTS M, K, KS, C, F0, OMEGA

MASS P1 = M, P2 = M, P3 = M, P4 = M, P5 = M

X1' = V1
X2' = V2
X3' = V3
X4' = V4
X5' = V5

P_NO_P1> = X1*N1>
P_NO_P2> = X2*N1>
P_NO_P3> = X3*N1>
P_NO_P4> = X4*N1>
P_NO_P5> = X5*N1>
V_P1_N> = V1*N1>
V_P2_N> = V2*N1>
V_P3_N> = V3*N1>
V_P4_N> = V4*N1>
V_P5_N> = V5*N1>

% wall: soft spring and damper on P1
FORCE(NO/P1, (-KS*X1 - C*V1)*N1>)
% stiff springs and light dampers between neighbours: +F> on the second, -F> on the first
FORCE(P1/P2, (-K*(X2 - X1) - C*(V2 - V1))*N1>)
FORCE(P2/P3, (-K*(X3 - X2) - C*(V3 - V2))*N1>)
FORCE(P3/P4, (-K*(X4 - X3) - C*(V4 - V3))*N1>)
FORCE(P4/P5, (-K*(X5 - X4) - C*(V5 - V4))*N1>)
% the drive on the last mass
FORCE(P5, F0*(1 - COS(OMEGA*T))*N1>)

ZERO = FR() + FRSTAR()
KANE()

INPUT M = 1 kg, K = 1.0E+04 N/m, KS = 20 N/m, C = 0.5 N*sec/m
INPUT F0 = 1 N, OMEGA = 3 rad/sec
INPUT X1 = 0, X2 = 0, X3 = 0, X4 = 0, X5 = 0
INPUT V1 = 0, V2 = 0, V3 = 0, V4 = 0, V5 = 0
INPUT TFINAL = 2, INTEGSTP = 0.1, ABSERR = 1.0E-08, RELERR = 1.0E-08
OUTPUT T sec, X1 m, X3 m, X5 m
CODE DYNAMICS() spring_chain.c
