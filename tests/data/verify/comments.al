% A model written for autolev's tests with Autolev-style response comments.
NEWTONIAN N
FRAMES A
VARIABLES Q'
CONSTANTS L
SIMPROT(N, A, 3, Q)
% -> N_A = [COS(Q), -SIN(Q), 0; SIN(Q), COS(Q), 0; 0, 0, 1]
W_A_N> = Q'*A3>
% -> W_A_N> = Q'*A3>
POINT O, P
P_O_P> = L*A1>
% -> P_O_P> = L*A1>
X = L*SIN(Q)^2
% -> X = L*SIN(Q)^2
Y = X + 1
% -> Y = 1 + L*SIN(Q)^2
