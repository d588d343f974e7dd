"""Translated from mass_spring_damper.al by autolev.

Importing this module builds the model; running it performs the model's
CODE commands with its INPUT values."""
import sympy as sm

import autolev.runtime as al

if __name__ == "__main__":
    # `python this.py [options]` is `autolev run this.py [options]`: the same
    # messages, files and exit status
    import sys

    from autolev.cli import main
    sys.exit(main(["run", __file__, *sys.argv[1:]]))

model = al.Model('mass_spring_damper')
t = model.t

# mass_spring_damper.al -- a cart on a vertical spring and damper, pushed by a
# prescribed force F(t).  X is measured down from the spring's unstretched end.

# NEWTONIAN N
N = model.newtonian('N')
NO = N.origin
# PARTICLES C                    % the cart
C = model.particles('C')
# MOTIONVARIABLES' X', V'
X, V = model.motion_variables('X V', order=1)
Xp = al.derivatives(X)
# CONSTANTS M, K, B, G, F0, OMEGA
M, K, B, G, F0, OMEGA = model.constants('M K B G F0 OMEGA')
# SPECIFIED F                    % a force prescribed as a function of time
F = model.specifieds('F')

# MASS C = M
C.mass = M
# X' = V
model.define(Xp, V)
# P_NO_C> = X*N1>
C.set_pos(NO, X*N.x)
# V_C_N> = V*N1>
C.set_vel(N, V*N.x)

# F = F0*SIN(OMEGA*T)
model.define(F, F0*sm.sin(OMEGA*t))
# GRAVITY(G*N1>)
model.gravity(G*N.x)
# FORCE(C, (-K*X - B*V + F)*N1>)
model.force(C, (-K*X - B*V + F)*N.x)

# ZERO = FR() + FRSTAR()
ZERO = model.fr() + model.frstar()
# KANE()
model.kane()

# INPUT M = 2 kg, K = 80 N/m, B = 1.5 N*sec/m, G = 9.81 m/sec^2
model.input(M, 2, 'kg')
model.input(K, 80, 'N/m')
model.input(B, 1.5, 'N*sec/m')
model.input(G, 9.81, 'm/sec^2')
# INPUT F0 = 3 N, OMEGA = 5 rad/sec
model.input(F0, 3, 'N')
model.input(OMEGA, 5, 'rad/sec')
# INPUT X = 0.1 m, V = 0 m/sec
model.input(X, 0.1, 'm')
model.input(V, 0, 'm/sec')
# INPUT TFINAL = 4, INTEGSTP = 0.02
model.input('TFINAL', 4)
model.input('INTEGSTP', 0.02)
# OUTPUT T sec, X m, V m/sec
model.output((t, 'T', 'sec'), (X, 'X', 'm'), (V, 'V', 'm/sec'))
# CODE DYNAMICS() mass_spring_damper.c
model.code('dynamics', 'mass_spring_damper.c', zero=ZERO)
