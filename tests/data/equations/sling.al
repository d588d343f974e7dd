% An arm A pinned at NO, a sling S hinged at its end, a particle P at the sling's end
% held on a horizontal line by the auxiliary constraint V_P_N> . N2> = 0, whose force
% FY is brought into evidence by KANE(FY).  Issue 49's model, for the autolev tests.
NEWTONIAN N
BODIES A
FRAMES S
PARTICLES P
MOTIONVARIABLES' Q{2}', U{2}'
VARIABLES FY
CONSTANTS LA, LS, MA, IA, MP, G
MASS A = MA, P = MP
INERTIA A, IA, IA, IA
SIMPROT(N, A, 3, Q1)
SIMPROT(A, S, 3, Q2)
Q1' = U1
Q2' = U2
P_NO_AO> = LA/2*A2>
P_NO_P> = LA*A2> + LS*S2>
V_AO_N> = DT(P_NO_AO>, N)
V_P_N> = DT(P_NO_P>, N)
AUXILIARY[1] = DOT(V_P_N>, N2>)
CONSTRAIN(AUXILIARY[U2])
FORCE_P> += FY*N2>
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE(FY)
INPUT LA = 1.0, LS = 0.8, MA = 2.0, IA = 0.5, MP = 0.3, G = 9.81
INPUT Q1 = 0.4, Q2 = 2.2, U1 = 0.7, U2 = 0.0
INPUT TFINAL = 0.5, INTEGSTP = 0.1
OUTPUT T, Q1, Q2, U1, FY
CODE DYNAMICS() sling.c
